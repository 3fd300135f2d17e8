#include "slump/ensemble_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "core/input_error.hpp"

namespace demscale::slump {

namespace {

std::vector<double> values(const std::vector<const SlumpResult*>& runs, double (*f)(const SlumpResult&)) {
    std::vector<double> v;
    for (const auto* r : runs) v.push_back(f(*r));
    return v;
}
double spread(const SlumpResult& r) { return r.final.spread; }

std::vector<double> mean_shape(const std::vector<std::vector<double>>& shapes, const std::vector<std::size_t>& pick) {
    std::vector<double> m(shapes.front().size(), 0.0);
    for (std::size_t i : pick)
        for (std::size_t j = 0; j < m.size(); ++j) m[j] += shapes[i][j] / static_cast<double>(pick.size());
    return m;
}

// The shapes a profile distance compares, one per seed: coarse and fine (wet minus dry with a
// control), and the fine wet shapes whose mean is the norm.
struct Shapes {
    std::vector<std::vector<double>> coarse, fine, norm;
    double distance(const std::vector<std::size_t>& ci, const std::vector<std::size_t>& fi) const {
        const auto c = mean_shape(coarse, ci), f = mean_shape(fine, fi), n = mean_shape(norm, fi);
        double d2 = 0, n2 = 0;
        for (std::size_t j = 0; j < c.size(); ++j) d2 += (c[j] - f[j]) * (c[j] - f[j]), n2 += n[j] * n[j];
        return n2 > 0 ? std::sqrt(d2 / n2) : 0.0;
    }
};

// Percentile bootstrap of the profile distance over the seeds of both sides.
stats::Interval bootstrap_profile(const Shapes& s) {
    std::mt19937_64 rng(20261201);
    std::uniform_int_distribution<std::size_t> pick_f(0, s.fine.size() - 1), pick_c(0, s.coarse.size() - 1);
    constexpr int resamples = 2000;
    std::vector<double> d;
    std::vector<std::size_t> fi(s.fine.size()), ci(s.coarse.size());
    for (int b = 0; b < resamples; ++b) {
        for (auto& i : fi) i = pick_f(rng);
        for (auto& i : ci) i = pick_c(rng);
        d.push_back(s.distance(ci, fi));
    }
    std::sort(d.begin(), d.end());
    return {d[static_cast<std::size_t>(0.025 * (resamples - 1))], d[static_cast<std::size_t>(0.975 * (resamples - 1))]};
}

std::vector<std::size_t> all_of(std::size_t n) {
    std::vector<std::size_t> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

}  // namespace

NoiseFloor noise_floor(const std::vector<const SlumpResult*>& fine, const FineReference& ref) {
    NoiseFloor n;
    n.slump_over_height = stats::summarize(values(fine, slump_over_height));
    n.spread = stats::summarize(values(fine, spread));
    std::vector<double> d;
    const double level = ref.piles.empty() ? 0 : fringe_level(ref.piles.front(), ref.piles.front());
    const auto mean = ref.shape(level);
    for (const auto* r : fine) d.push_back(shape_distance(pile_shape(r->final, ref.radii, level), mean));
    n.profile = stats::summarize(d);
    return n;
}

double slump_over_height(const SlumpResult& r) { return r.slump() / r.initial_height; }

EnsembleVerdict judge_ensemble(const std::vector<const SlumpResult*>& fine, const std::vector<const SlumpResult*>& coarse,
                               double sf, double exponent, const Tolerances& tol, double fine_radius, bool wet,
                               const DryControl* control) {
    EnsembleVerdict v;
    v.sf = sf, v.exponent = exponent, v.fine_seeds = fine.size(), v.coarse_seeds = coarse.size();
    if (fine.empty() || coarse.empty()) return v;
    if (control && (control->fine.size() != fine.size() || control->coarse.size() != coarse.size()))
        throw std::invalid_argument("judge_ensemble: the dry control must hold the same seeds as the wet ensembles");
    double reach = 0;
    for (const auto* r : coarse) reach = std::max(reach, r->final.spread_max);
    if (control)
        for (const auto& side : {control->fine, control->coarse})
            for (const auto* r : side) reach = std::max(reach, r->final.spread_max);
    const auto ref = fine_reference(fine, fine_radius, reach);
    const auto noise = noise_floor(fine, ref);
    const bool too_few = fine.size() < 2 || coarse.size() < 2;

    auto criterion = [&](const std::string& measure, double estimate, stats::Interval interval, double tolerance) {
        Criterion c{measure, estimate, interval, tolerance, stats::equivalence_verdict(interval, tolerance),
                    stats::smallest_confirmable_tolerance(interval), ""};
        if (too_few) c.verdict = stats::Verdict::inconclusive, c.reason = "fewer than two seeds on a side: no interval";
        return c;
    };
    // Each seed's value, less its dry twin's with a control.
    auto seedwise = [&](const std::vector<const SlumpResult*>& runs, const std::vector<const SlumpResult*>* dry,
                        double (*f)(const SlumpResult&)) {
        auto x = values(runs, f);
        if (dry)
            for (std::size_t i = 0; i < x.size(); ++i) x[i] -= f(*(*dry)[i]);
        return x;
    };
    const auto* dry_fine = control ? &control->fine : nullptr;
    const auto* dry_coarse = control ? &control->coarse : nullptr;
    // Slump over H₀, absolute.
    const auto fs = seedwise(fine, dry_fine, slump_over_height), cs = seedwise(coarse, dry_coarse, slump_over_height);
    auto slump = criterion("slump", stats::summarize(cs).mean - stats::summarize(fs).mean, stats::difference_interval(fs, cs), tol.slump);
    double fine_slump = 0;
    for (const auto* r : fine) fine_slump += r->slump() / static_cast<double>(fine.size());
    if (fine_slump < 2 * sf * fine_radius) {
        slump.verdict = stats::Verdict::inconclusive;
        slump.reason = "the fine reference slumps " + format_short(fine_slump * 1e3, 3) + " mm, less than one coarse diameter (" +
                       format_short(2 * sf * fine_radius * 1e3, 3) + " mm): this scene cannot tell exponents apart by slump";
    }
    // Spread (diameter at half height), relative to the fine mean.
    const auto fd = seedwise(fine, dry_fine, spread), cd = seedwise(coarse, dry_coarse, spread);
    const double mean_fd = stats::summarize(values(fine, spread)).mean;
    const auto dd = stats::difference_interval(fd, cd);
    auto spread = criterion("spread", (stats::summarize(cd).mean - stats::summarize(fd).mean) / mean_fd, {dd.low / mean_fd, dd.high / mean_fd},
                            tol.spread);
    // Profile: distance of the mean shapes, bootstrapped.
    const double level = fringe_level(fine.front()->final, coarse.front()->final);
    auto shapes_of = [&](const std::vector<const SlumpResult*>& runs, const std::vector<const SlumpResult*>* dry) {
        std::vector<std::vector<double>> s;
        for (std::size_t i = 0; i < runs.size(); ++i) {
            s.push_back(pile_shape(runs[i]->final, ref.radii, level));
            if (dry) {
                const auto d = pile_shape((*dry)[i]->final, ref.radii, level);
                for (std::size_t j = 0; j < d.size(); ++j) s.back()[j] -= d[j];
            }
        }
        return s;
    };
    const Shapes shapes{shapes_of(coarse, dry_coarse), shapes_of(fine, dry_fine), shapes_of(fine, nullptr)};
    const double distance = shapes.distance(all_of(coarse.size()), all_of(fine.size()));
    auto profile = criterion("profile", distance, too_few ? stats::Interval{distance, distance} : bootstrap_profile(shapes), tol.profile);

    v.criteria = {slump, spread, profile};
    v.overall = stats::combine({slump.verdict, spread.verdict, profile.verdict});
    auto below_noise = [&](const char* what, double tolerance, double scatter) {
        if (fine.size() >= 2 && tolerance < scatter)
            v.warnings.push_back(std::string(what) + " tolerance " + format_short(100 * tolerance, 3) + " % is below the fine ensemble's own spread (" +
                                 format_short(100 * scatter, 3) + " %)");
    };
    below_noise("slump", tol.slump, noise.slump_over_height.sd);
    below_noise("spread", tol.spread, noise.spread.sd / noise.spread.mean);
    below_noise("profile", tol.profile, noise.profile.mean);
    if (!wet) v.warnings.push_back("dry scene: k scales only the surface tension, which it does not use; the exponent has no effect");
    return v;
}

}  // namespace demscale::slump
