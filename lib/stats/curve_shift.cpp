#include "stats/curve_shift.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_interp.h>
#include <memory>
#include <numeric>
#include <random>
#include <stdexcept>

namespace demscale::stats {

namespace {

double mean_of(const ResponseLevel& l) { return std::accumulate(l.y.begin(), l.y.end(), 0.0) / static_cast<double>(l.y.size()); }

// A curve reduced to its ensemble means, sorted by x, with its interpolant.
struct MeanCurve {
    double log_sf = 0;
    std::vector<double> x, y;
    std::shared_ptr<gsl_interp> steffen;  // three or more levels; else linear
};

double mean_of(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }

// offset: subtracted from every level's mean (a coarse curve's control offset).
MeanCurve means_of(const ResponseCurve& c, double offset = 0) {
    std::vector<const ResponseLevel*> sorted;
    for (const auto& l : c.levels) sorted.push_back(&l);
    std::sort(sorted.begin(), sorted.end(), [](const auto* a, const auto* b) { return a->x < b->x; });
    MeanCurve m;
    m.log_sf = std::log(c.sf);
    for (const auto* l : sorted) {
        if (!m.x.empty() && !(l->x > m.x.back())) throw std::invalid_argument("two response levels at the same x");
        m.x.push_back(l->x);
        m.y.push_back(mean_of(*l) - offset);
    }
    if (m.x.size() >= 3) {
        m.steffen.reset(gsl_interp_alloc(gsl_interp_steffen, m.x.size()), gsl_interp_free);
        gsl_interp_init(m.steffen.get(), m.x.data(), m.y.data(), m.x.size());
    }
    return m;
}

double interpolate(const MeanCurve& f, double x) {
    if (x <= f.x.front()) return f.y.front();
    if (x >= f.x.back()) return f.y.back();
    if (f.steffen) return gsl_interp_eval(f.steffen.get(), f.x.data(), f.y.data(), x, nullptr);
    const double t = (x - f.x[0]) / (f.x[1] - f.x[0]);
    return f.y[0] + t * (f.y[1] - f.y[0]);
}

// What k̂ minimises: Σ (ȳ − y_fine(x − k ln S_f))² over every level of the coarse curves.
double objective(const MeanCurve& fine, const std::vector<MeanCurve>& coarse, double k) {
    double sum = 0;
    for (const auto& c : coarse)
        for (std::size_t j = 0; j < c.x.size(); ++j) {
            const double r = c.y[j] - interpolate(fine, c.x[j] - k * c.log_sf);
            sum += r * r;
        }
    return sum;
}

// The k in [k_min, k_max] that minimises the objective: the best point of a grid of 0.05, then
// golden section between its neighbours (the objective is piecewise quadratic in k). Of equal
// values on a plateau the grid keeps the middle one, so a flat objective does not drift to a bound;
// unique is false then (the coarse levels lie where the fine curve is flat: no shift is preferred).
struct Shift {
    double k;
    bool unique;
};
Shift best_shift(const MeanCurve& fine, const std::vector<MeanCurve>& coarse, const ShiftSearch& s) {
    const double step = 0.05;
    const int n = static_cast<int>(std::ceil((s.k_max - s.k_min) / step));
    std::vector<double> value(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) value[static_cast<std::size_t>(i)] = objective(fine, coarse, std::min(s.k_min + i * step, s.k_max));
    const double least = *std::min_element(value.begin(), value.end());
    std::vector<int> ties;
    for (int i = 0; i <= n; ++i)
        if (value[static_cast<std::size_t>(i)] <= least * (1 + 1e-9) + 1e-15) ties.push_back(i);
    const int best = ties[ties.size() / 2];
    const bool unique = ties.back() - ties.front() <= 2;
    double a = std::max(s.k_min, s.k_min + (best - 1) * step), b = std::min(s.k_max, s.k_min + (best + 1) * step);
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - golden * (b - a), d = a + golden * (b - a);
    double fc = objective(fine, coarse, c), fd = objective(fine, coarse, d);
    for (int it = 0; it < 40; ++it) {
        if (fc <= fd) b = d, d = c, fd = fc, c = b - golden * (b - a), fc = objective(fine, coarse, c);
        else a = c, c = d, fc = fd, d = a + golden * (b - a), fd = objective(fine, coarse, d);
    }
    const double refined = 0.5 * (a + b);
    return {objective(fine, coarse, refined) <= least ? refined : std::min(s.k_min + best * step, s.k_max), unique};
}


}  // namespace

void check_response_curves(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse) {
    if (fine.levels.size() < 2) throw std::invalid_argument("the fine response curve needs at least two levels");
    auto check_levels = [](const ResponseCurve& c) {
        for (const auto& l : c.levels)
            if (l.y.empty() || !std::isfinite(l.x)) throw std::invalid_argument("a response level without runs or with a non-finite x");
    };
    check_levels(fine);
    for (const auto& c : coarse) {
        if (!(c.sf > 1) || c.levels.empty()) throw std::invalid_argument("a coarse response curve needs S_f > 1 and at least one level");
        check_levels(c);
    }
}

double interpolate_response(const ResponseCurve& fine, double x) { return interpolate(means_of(fine), x); }

double control_offset(const ResponseCurve& fine, const ResponseCurve& coarse) {
    if (fine.control.y.empty() || coarse.control.y.empty()) return 0.0;
    return mean_of(coarse.control.y) - mean_of(fine.control.y);
}

std::vector<long> ResponseCurve::seeds() const {
    std::vector<long> all;
    auto add = [&](const ResponseLevel& l) {
        for (std::size_t i = 0; i < l.y.size(); ++i) all.push_back(l.seed_at(i));
    };
    add(control);
    for (const auto& l : levels) add(l);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

namespace {
// The level's values of the drawn seeds, in the draw's order (a seed drawn twice twice).
std::vector<double> values_of(const ResponseLevel& l, const std::vector<long>& drawn) {
    std::vector<double> y;
    for (long s : drawn)
        for (std::size_t i = 0; i < l.y.size(); ++i)
            if (l.seed_at(i) == s) y.push_back(l.y[i]);
    return y;
}
}  // namespace

ResponseCurve resample_by_seed(const ResponseCurve& c, std::mt19937_64& rng) {
    const std::vector<long> seeds = c.seeds();
    ResponseCurve r = c;
    if (seeds.empty()) return r;
    std::uniform_int_distribution<std::size_t> pick(0, seeds.size() - 1);
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::vector<long> drawn(seeds.size());
        for (auto& s : drawn) s = seeds[pick(rng)];
        bool every_level = true;
        for (std::size_t i = 0; i < c.levels.size(); ++i) {
            r.levels[i].y = values_of(c.levels[i], drawn);
            every_level = every_level && !r.levels[i].y.empty();
        }
        if (!c.control.y.empty()) r.control.y = values_of(c.control, drawn);
        every_level = every_level && (c.control.y.empty() || !r.control.y.empty());
        if (every_level) {
            for (auto& l : r.levels) l.seed.clear();  // resampled values carry no seed identity any more
            r.control.seed.clear();
            return r;
        }
    }
    return c;
}

std::vector<SplitLevel> split_levels(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse) {
    std::vector<const ResponseCurve*> curves{&fine};
    for (const auto& c : coarse) curves.push_back(&c);
    double lo = INFINITY, hi = -INFINITY;  // the span of the level means
    for (const auto* c : curves)
        for (const auto& l : c->levels)
            if (!l.y.empty()) lo = std::min(lo, mean_of(l)), hi = std::max(hi, mean_of(l));
    std::vector<SplitLevel> split;
    if (!(hi > lo)) return split;  // no response to split across
    const double third = (hi - lo) / 3;
    for (const auto* c : curves)
        for (const auto& l : c->levels) {
            SplitLevel s{c->sf, l.x, 0, 0, l.y.size()};
            for (double y : l.y) s.low += y <= lo + third, s.high += y >= hi - third;
            if (s.low > 0 && s.high > 0) split.push_back(s);
        }
    return split;
}

double shift_residual_rms(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse, double k) {
    check_response_curves(fine, coarse);
    std::vector<MeanCurve> c;
    std::size_t levels = 0;
    for (const auto& curve : coarse) c.push_back(means_of(curve, control_offset(fine, curve))), levels += curve.levels.size();
    return std::sqrt(objective(means_of(fine), c, k) / static_cast<double>(levels));
}

std::vector<ExponentEstimate> estimate_exponent(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse,
                                                const ShiftSearch& search) {
    check_response_curves(fine, coarse);
    if (!(search.k_min < search.k_max) || search.resamples < 10) throw std::invalid_argument("a bad exponent search");
    // The sets to estimate from: each coarse curve alone, then all together.
    std::vector<std::vector<std::size_t>> sets;
    for (std::size_t i = 0; i < coarse.size(); ++i) sets.push_back({i});
    if (coarse.size() > 1) {
        sets.emplace_back(coarse.size());
        std::iota(sets.back().begin(), sets.back().end(), std::size_t{0});
    }
    auto estimate_all = [&](const ResponseCurve& f, const std::vector<ResponseCurve>& cs) {
        const MeanCurve fm = means_of(f);
        std::vector<MeanCurve> cm;
        for (const auto& c : cs) cm.push_back(means_of(c, control_offset(f, c)));
        std::vector<Shift> k;
        for (const auto& set : sets) {
            std::vector<MeanCurve> chosen;
            for (std::size_t i : set) chosen.push_back(cm[i]);
            k.push_back(best_shift(fm, chosen, search));
        }
        return k;
    };
    const std::vector<Shift> k_hat = estimate_all(fine, coarse);
    std::vector<std::vector<double>> boot(sets.size());
    std::mt19937_64 rng(search.seed);
    for (int b = 0; b < search.resamples; ++b) {
        const ResponseCurve f = resample_by_seed(fine, rng);
        std::vector<ResponseCurve> cs;
        for (const auto& c : coarse) cs.push_back(resample_by_seed(c, rng));
        const std::vector<Shift> k = estimate_all(f, cs);
        for (std::size_t s = 0; s < sets.size(); ++s) boot[s].push_back(k[s].k);
    }
    const std::vector<SplitLevel> split = split_levels(fine, coarse);
    std::vector<ExponentEstimate> out;
    for (std::size_t s = 0; s < sets.size(); ++s) {
        std::vector<double>& v = boot[s];
        std::sort(v.begin(), v.end());
        auto quantile = [&](double q) { return v[static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)))]; };
        ExponentEstimate e;
        e.sf = sets[s].size() == 1 && s < coarse.size() ? coarse[s].sf : 0.0;
        e.k = k_hat[s].k;
        e.ci = {quantile(0.025), quantile(0.975)};
        std::vector<ResponseCurve> chosen;
        for (std::size_t i : sets[s]) chosen.push_back(coarse[i]);
        e.rms = shift_residual_rms(fine, chosen, e.k);
        if (chosen.size() == 1) e.offset = control_offset(fine, chosen.front());
        const double margin = 0.051;  // one grid step: an interval touching a bound reached it
        e.determined = k_hat[s].unique && e.ci.low > search.k_min + margin && e.ci.high < search.k_max - margin;
        for (const SplitLevel& l : split)
            e.split_levels += l.sf == 1 || std::any_of(chosen.begin(), chosen.end(), [&](const auto& c) { return c.sf == l.sf; });
        out.push_back(e);
    }
    return out;
}

}  // namespace demscale::stats
