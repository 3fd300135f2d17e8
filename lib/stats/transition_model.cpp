#include "stats/transition_model.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sf_erf.h>
#include <numeric>
#include <stdexcept>

namespace demscale::stats {

namespace {

constexpr double chi2_1_95 = 3.841458820694124;  // χ²₁ quantile at 0.95

// The deviance a 95 % interval admits. χ²₁ holds for many runs; with n slumped runs and p parameters
// of the continuous part (k included) the σ estimated from the same runs makes it too narrow, and the
// exact cutoff of a linear model, n ln(1 + F₁,ₙ₋ₚ(0.95) / (n − p)), is used where it is larger
// (for 40 runs and 6 parameters 4.6 instead of 3.84).
double deviance_cutoff(std::size_t n, std::size_t p) {
    if (n <= p + 1) return chi2_1_95;
    const double dof = static_cast<double>(n - p);
    return std::max(chi2_1_95, static_cast<double>(n) * std::log1p(gsl_cdf_fdist_Pinv(0.95, 1, dof) / dof));
}

// ln Φ(z), accurate far into both tails.
double log_phi_cdf(double z) { return std::log(0.5) + gsl_sf_log_erfc(-z / std::sqrt(2.0)); }
// φ(z)/Φ(z), the inverse Mills ratio.
double mills(double z) { return std::exp(-0.5 * z * z - 0.5 * std::log(2 * M_PI) - log_phi_cdf(z)); }

struct WetRun {
    double x, log_sf, y;
    bool stands;
    bool on_branch;     // slumped, at a level where no run stood: a point of the continuous part
    std::size_t curve;  // 0 fine, then the chosen coarse curves
    double variance;    // of its level, shrunk towards its curve's (on the branch only)
};

struct Data {
    std::vector<WetRun> wet;
    std::vector<std::vector<double>> control;  // per curve; all empty: no offsets
    std::vector<double> control_variance;      // per curve, shrunk towards the controls' pooled one
    bool controls = false;
    int degree = 1;        // of the slumped branch
    double centre = 0;     // ū
    std::size_t standing = 0, slumped = 0, on_branch = 0;
    double standing_slump = 0;
    bool quantal() const { return standing > 0 && slumped > 0; }
};

// The run-to-run variance of each group of runs (a level, a control), shrunk towards the pool of
// its kind: (ν₀ s²_pool + (n − 1) s²) / (ν₀ + n − 1), ν₀ = 3. The spread grows towards the
// transition and with S_f (docs/exponent-estimate.md); with 4 seeds a level's own s² has 3 degrees
// of freedom, too few to weight by alone.
std::vector<double> shrunk_variances(const std::vector<std::vector<double>>& groups) {
    constexpr double prior_dof = 3, floor = 1e-8;  // floor: (1e-4 of the fill height)²
    std::vector<double> own(groups.size(), 0), dof(groups.size(), 0);
    double pooled_ss = 0, pooled_dof = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const auto& y = groups[g];
        if (y.size() < 2) continue;
        const double mean = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(y.size());
        double ss = 0;
        for (double v : y) ss += (v - mean) * (v - mean);
        dof[g] = static_cast<double>(y.size() - 1), own[g] = ss / dof[g];
        pooled_ss += ss, pooled_dof += dof[g];
    }
    const double pooled = pooled_dof > 0 ? pooled_ss / pooled_dof : floor;
    std::vector<double> out(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g)
        out[g] = std::max(floor, (prior_dof * pooled + dof[g] * own[g]) / (prior_dof + dof[g]));
    return out;
}

// A level is on the slumped branch when none of its runs stood.
bool on_branch(const ResponseLevel& l, const TransitionSettings& s) {
    return std::none_of(l.y.begin(), l.y.end(), [&](double y) { return y < s.stands_below; });
}

// The runs of the curves. `classified` says which levels are on the branch: the same curves, or the
// full ones when a jackknife has taken a seed out (the branch then keeps its levels, so that the
// jackknife measures the runs' noise, not a level that changes sides).
Data gather(const std::vector<const ResponseCurve*>& curves, const TransitionSettings& s, const std::vector<const ResponseCurve*>& classified) {
    Data d;
    std::size_t fine_slumped_levels = 0;
    double fine_x = 0;
    std::size_t fine_n = 0;
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const auto& levels = curves[c]->levels;
        std::vector<bool> pure(levels.size());
        std::vector<std::vector<double>> branch_levels;
        for (std::size_t j = 0; j < levels.size(); ++j)
            if ((pure[j] = on_branch(classified[c]->levels[j], s)) && !levels[j].y.empty()) branch_levels.push_back(levels[j].y);
        const std::vector<double> variance = shrunk_variances(branch_levels);
        std::size_t branch_level = 0;
        for (std::size_t j = 0; j < levels.size(); ++j) {
            const auto& l = levels[j];
            if (l.y.empty()) continue;
            const double level_variance = pure[j] ? variance[branch_level++] : 0.0;
            for (double y : l.y) {
                const bool stands = y < s.stands_below;
                d.wet.push_back({l.x, std::log(curves[c]->sf), y, stands, pure[j], c, level_variance});
                if (stands) d.standing++, d.standing_slump += y;
                else d.slumped++;
                if (pure[j]) d.on_branch++;
                if (pure[j] && c == 0) fine_x += l.x, fine_n++;
            }
            fine_slumped_levels += pure[j] && c == 0;
        }
    }
    if (d.standing > 0) d.standing_slump /= static_cast<double>(d.standing);
    d.centre = fine_n > 0 ? fine_x / static_cast<double>(fine_n) : 0.0;
    // The branch's shape comes from the fine levels alone, so that no shift of the coarse ones can
    // lend it a curvature (coarse levels that land on fine ones at some k would otherwise change
    // the polynomial's rank there).
    d.degree = fine_slumped_levels >= 3 ? 2 : fine_slumped_levels >= 2 ? 1 : 0;
    d.controls = std::all_of(curves.begin(), curves.end(), [](const auto* c) { return !c->control.y.empty(); });
    if (d.controls) {
        for (const auto* c : curves) d.control.push_back(c->control.y);
        d.control_variance = shrunk_variances(d.control);
    }
    return d;
}

Data gather(const std::vector<const ResponseCurve*>& curves, const TransitionSettings& s) { return gather(curves, s, curves); }

// The probit part at one k: its maximum log-likelihood, α and β of z = α + β u kept for a warm start.
struct Probit {
    double a = 0, b = 0;
    bool started = false;
};

double probit_loglik(const Data& d, double k, double a, double b) {
    double ll = 0;
    for (const auto& r : d.wet) {
        const double z = a + b * (r.x - k * r.log_sf);
        ll += log_phi_cdf(r.stands ? z : -z);
    }
    return ll;
}

double fit_probit(const Data& d, double k, double b_max, Probit& p) {
    if (!p.started) {  // threshold midway between the kinds' mean u, width 0.3
        double su = 0, ss = 0;
        for (const auto& r : d.wet) (r.stands ? su : ss) += r.x - k * r.log_sf;
        const double mid = 0.5 * (su / static_cast<double>(d.standing) + ss / static_cast<double>(d.slumped));
        p.b = std::min(b_max, 1 / 0.3), p.a = -p.b * mid, p.started = true;
    }
    double ll = probit_loglik(d, k, p.a, p.b);
    for (int it = 0; it < 100; ++it) {
        double ga = 0, gb = 0, haa = 0, hab = 0, hbb = 0;
        for (const auto& r : d.wet) {
            const double u = r.x - k * r.log_sf, z = p.a + p.b * u;
            const double sign = r.stands ? 1.0 : -1.0, lam = mills(sign * z);
            const double g = sign * lam, h = -lam * (sign * z + lam);  // d/dz and d²/dz² of ln Φ(±z)
            ga += g, gb += g * u, haa += h, hab += h * u, hbb += h * u * u;
        }
        // Newton step; on the bounds of β (0 and b_max) the step in α alone.
        const double det = haa * hbb - hab * hab;
        double da = 0, db = 0;
        const bool at_bound = (p.b >= b_max && gb > 0) || (p.b <= 0 && gb < 0);
        if (!at_bound && det > 1e-300) da = -(hbb * ga - hab * gb) / det, db = -(haa * gb - hab * ga) / det;
        else da = haa < 0 ? -ga / haa : 0;
        double step = 1, next = ll;
        double na = p.a, nb = p.b;
        for (int half = 0; half < 40; ++half, step *= 0.5) {
            na = p.a + step * da, nb = std::clamp(p.b + step * db, 0.0, b_max);
            next = probit_loglik(d, k, na, nb);
            if (next >= ll) break;
        }
        if (!(next >= ll)) break;
        const bool small = std::abs(na - p.a) + std::abs(nb - p.b) < 1e-10;
        p.a = na, p.b = nb;
        const double gain = next - ll;
        ll = next;
        if (small || gain < 1e-12) break;
    }
    return ll;
}

// The continuous part at one k: weighted least squares, each run weighted by its group's shrunk
// variance times a scale (one for the wet runs, one for the dry) re-estimated by maximum
// likelihood, and its log-likelihood.
struct Branch {
    Eigen::VectorXd p;  // β₀, β₁[, β₂], then d per curve
    double sigma = 0;   // root mean square residual of the wet runs
    double loglik = 0;
};

Branch fit_branch(const Data& d, double k) {
    const int nb = d.degree + 1, nd = d.controls ? static_cast<int>(d.control.size()) : 0;
    std::size_t rows = d.on_branch;
    for (const auto& c : d.control) rows += d.controls ? c.size() : 0;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), nb + nd);
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows)), variance(static_cast<Eigen::Index>(rows));
    std::vector<bool> dry(rows, false);
    Eigen::Index i = 0;
    for (const auto& r : d.wet) {
        if (!r.on_branch) continue;
        const double v = r.x - k * r.log_sf - d.centre;
        for (int j = 0; j < nb; ++j) A(i, j) = std::pow(v, j);
        if (nd > 0 && r.curve > 0) A(i, nb + static_cast<int>(r.curve)) = 1, A(i, nb) = -1;
        variance(i) = r.variance;
        y(i++) = r.y;
    }
    for (int c = 0; c < nd; ++c)
        for (double v : d.control[static_cast<std::size_t>(c)]) {
            A(i, nb + c) = 1, dry[static_cast<std::size_t>(i)] = true;
            variance(i) = d.control_variance[static_cast<std::size_t>(c)];
            y(i++) = v;
        }
    Branch b;
    double scale = 1, scale_dry = 1;  // of the variances
    for (int it = 0; it < 8; ++it) {
        const double previous = scale, previous_dry = scale_dry;
        Eigen::VectorXd w(A.rows());
        for (Eigen::Index r = 0; r < A.rows(); ++r) w(r) = 1 / std::sqrt((dry[static_cast<std::size_t>(r)] ? scale_dry : scale) * variance(r));
        b.p = (w.asDiagonal() * A).completeOrthogonalDecomposition().solve(w.asDiagonal() * y);
        const Eigen::VectorXd res = y - A * b.p;
        double ss = 0, ss_dry = 0, raw = 0;
        std::size_t n = 0, n_dry = 0;
        for (Eigen::Index r = 0; r < A.rows(); ++r) {
            const double z = res(r) * res(r) / variance(r);
            if (dry[static_cast<std::size_t>(r)]) ss_dry += z, n_dry++;
            else ss += z, raw += res(r) * res(r), n++;
        }
        constexpr double least = 1e-6;  // of the scale: noiseless data keep a finite likelihood
        scale = std::max(least, n ? ss / static_cast<double>(n) : 1.0);
        scale_dry = std::max(least, n_dry ? ss_dry / static_cast<double>(n_dry) : 1.0);
        b.sigma = n ? std::sqrt(raw / static_cast<double>(n)) : 0.0;
        b.loglik = 0;
        for (Eigen::Index r = 0; r < A.rows(); ++r) {
            const double s2 = (dry[static_cast<std::size_t>(r)] ? scale_dry : scale) * variance(r);
            b.loglik += -0.5 * std::log(2 * M_PI * s2) - 0.5 * res(r) * res(r) / s2;
        }
        if (std::abs(scale - previous) < 1e-6 * scale && std::abs(scale_dry - previous_dry) < 1e-6 * scale_dry) break;
    }
    return b;
}

struct AtK {
    double loglik;
    Probit probit;
    Branch branch;
};

AtK evaluate(const Data& d, double k, const TransitionSettings& s, Probit warm) {
    AtK r{0, warm, {}};
    if (d.quantal()) r.loglik += fit_probit(d, k, 1 / s.min_width, r.probit);
    if (d.on_branch > 0) {
        r.branch = fit_branch(d, k);
        r.loglik += r.branch.loglik;
    }
    return r;
}

// The maximum of ℓ(k) over [lo, hi]: a grid of 0.1, each point warm-started from its neighbour's
// probit, then golden section between the best grid point's neighbours.
struct Maximum {
    double k = 0, loglik = 0;
    std::size_t best = 0;              // grid index nearest the maximum
    std::vector<double> grid, values;  // k and ℓ(k) on the grid
    std::vector<Probit> probits;       // per grid point, for warm starts near it
    double at(const Data& d, const TransitionSettings& s, double where) const {
        const double step = grid.size() > 1 ? grid[1] - grid[0] : 1;
        const auto i = static_cast<std::size_t>(std::clamp(std::lround((where - grid.front()) / step), 0L, static_cast<long>(grid.size() - 1)));
        return evaluate(d, where, s, probits[i]).loglik;
    }
};

constexpr double grid_step = 0.1;  // of the profile's search grid in k

Maximum maximise(const Data& d, const TransitionSettings& s, double lo, double hi) {
    Maximum m;
    const double step = grid_step;
    const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / step)));
    Probit warm;
    for (int i = 0; i <= n; ++i) {
        const double k = std::min(lo + i * step, hi);
        const AtK at = evaluate(d, k, s, warm);
        warm = at.probit;
        m.probits.push_back(warm), m.grid.push_back(k), m.values.push_back(at.loglik);
    }
    m.best = static_cast<std::size_t>(std::max_element(m.values.begin(), m.values.end()) - m.values.begin());
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    double a = m.grid[m.best > 0 ? m.best - 1 : 0], b = m.grid[std::min(m.best + 1, m.grid.size() - 1)];
    double c = b - golden * (b - a), e = a + golden * (b - a), fc = m.at(d, s, c), fe = m.at(d, s, e);
    for (int it = 0; it < 30; ++it) {
        if (fc >= fe) b = e, e = c, fe = fc, c = b - golden * (b - a), fc = m.at(d, s, c);
        else a = c, c = e, fc = fe, e = a + golden * (b - a), fe = m.at(d, s, e);
    }
    m.k = 0.5 * (a + b), m.loglik = m.at(d, s, m.k);
    if (m.loglik < m.values[m.best]) m.k = m.grid[m.best], m.loglik = m.values[m.best];
    return m;
}

// The curve without a group of seeds' runs (a level left empty stays, empty, so that levels keep
// their index).
ResponseCurve without_seeds(const ResponseCurve& c, const std::vector<long>& gone) {
    auto keep = [&](const ResponseLevel& l) {
        ResponseLevel out;
        out.x = l.x;
        for (std::size_t i = 0; i < l.y.size(); ++i)
            if (std::find(gone.begin(), gone.end(), l.seed_at(i)) == gone.end()) out.y.push_back(l.y[i]), out.seed.push_back(l.seed_at(i));
        return out;
    };
    ResponseCurve out;
    out.sf = c.sf, out.control = keep(c.control);
    for (const auto& l : c.levels) out.levels.push_back(keep(l));
    return out;
}

// The delete-one-seed jackknife of k-hat: a seed's runs at every level and in the control leave
// together, curve by curve (fine and coarse seeds are independent). Its variance,
// Σ_c (g_c − 1)/g_c Σ_j (k̂₋ⱼ − k̄_c)², does not lean on the model's noise being right; its degrees of
// freedom are Σ_c (g_c − 1) over curves with at least two seeds. Beyond 10 seeds a curve's seeds
// leave in 10 groups (the grouped jackknife), which bounds the cost.
void seed_jackknife(const std::vector<const ResponseCurve*>& curves, const TransitionSettings& s, TransitionFit& f) {
    double variance = 0;
    std::size_t dof = 0;
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const auto seeds = curves[c]->seeds();
        if (seeds.size() < 2) continue;
        const std::size_t groups = std::min<std::size_t>(seeds.size(), 10);
        std::vector<double> k;
        for (std::size_t g = 0; g < groups; ++g) {
            std::vector<long> gone;
            for (std::size_t i = g; i < seeds.size(); i += groups) gone.push_back(seeds[i]);
            ResponseCurve reduced = without_seeds(*curves[c], gone);
            std::vector<const ResponseCurve*> set = curves;
            set[c] = &reduced;
            const Data d = gather(set, s, curves);
            if (d.wet.empty()) return;  // nothing left to fit: no jackknife
            k.push_back(maximise(d, s, std::max(s.k_min, f.k - 1.5), std::min(s.k_max, f.k + 1.5)).k);
        }
        const double n = static_cast<double>(k.size()), mean = std::accumulate(k.begin(), k.end(), 0.0) / n;
        for (double v : k) variance += (n - 1) / n * (v - mean) * (v - mean);
        dof += k.size() - 1;
    }
    if (dof < 2) return;
    f.jackknife_se = std::sqrt(variance), f.jackknife_dof = dof;
    const double half = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(dof)) * f.jackknife_se;
    f.ci = {std::min(f.profile_ci.low, f.k - half), std::max(f.profile_ci.high, f.k + half)};
}

// Whether the coarse branch lies beyond the fine one at k̂: a coarse curve a third or more of whose
// slumped-branch runs sit further than 0.15 in ln γ outside the fine branch's levels is read off an
// extrapolated polynomial.
bool extrapolated(const Data& d, double k) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& r : d.wet)
        if (r.curve == 0 && r.on_branch) lo = std::min(lo, r.x), hi = std::max(hi, r.x);
    if (!(lo <= hi)) return false;
    std::vector<std::size_t> outside, total;
    for (const auto& r : d.wet) {
        if (r.curve == 0 || !r.on_branch) continue;
        if (r.curve >= total.size()) total.resize(r.curve + 1, 0), outside.resize(r.curve + 1, 0);
        const double u = r.x - k * r.log_sf;
        total[r.curve]++, outside[r.curve] += u < lo - 0.15 || u > hi + 0.15;
    }
    for (std::size_t c = 1; c < total.size(); ++c)
        if (total[c] > 0 && 3 * outside[c] >= total[c]) return true;
    return false;
}

TransitionFit fit_set(const std::vector<const ResponseCurve*>& curves, double sf, const TransitionSettings& s) {
    const Data d = gather(curves, s);
    TransitionFit f;
    f.sf = sf;
    f.standing = d.standing, f.slumped = d.slumped, f.quantal = d.quantal(), f.centre = d.centre;
    f.standing_slump = d.standing_slump;
    const Maximum m = maximise(d, s, s.k_min, s.k_max);
    const double k_hat = m.k, ll_hat = m.loglik;
    f.profile_k = m.grid;
    for (double v : m.values) f.profile_deviance.push_back(std::max(0.0, 2 * (ll_hat - v)));
    const std::size_t wet_params = static_cast<std::size_t>(d.degree + 2) + (d.controls ? curves.size() - 1 : 0);
    f.cutoff = deviance_cutoff(d.on_branch, wet_params);
    // The interval: from k̂ itself (deviance 0) outward to the first grid point beyond the cutoff,
    // then bisection (the part of {k : deviance ≤ cutoff} that holds k̂). Not from the grid point
    // nearest k̂: with many runs the profile is narrower than the grid step, and that point can lie
    // outside the set already.
    const int n = static_cast<int>(m.grid.size()) - 1;
    auto crossing = [&](int dir) -> double {
        double inside = k_hat;
        int i = static_cast<int>(m.best);
        while (i >= 0 && i <= n && (dir > 0 ? m.grid[static_cast<std::size_t>(i)] <= k_hat : m.grid[static_cast<std::size_t>(i)] >= k_hat)) i += dir;
        for (; i >= 0 && i <= n && f.profile_deviance[static_cast<std::size_t>(i)] <= f.cutoff; i += dir) inside = m.grid[static_cast<std::size_t>(i)];
        if (i < 0 || i > n) return dir < 0 ? s.k_min : s.k_max;
        double outside = m.grid[static_cast<std::size_t>(i)];
        for (int it = 0; it < 30; ++it) {
            const double mid = 0.5 * (inside + outside);
            (2 * (ll_hat - m.at(d, s, mid)) <= f.cutoff ? inside : outside) = mid;
        }
        return 0.5 * (inside + outside);
    };
    f.k = k_hat;
    f.profile_ci = f.ci = {crossing(-1), crossing(+1)};
    const double margin = grid_step + 1e-9;
    f.determined = f.ci.low > s.k_min + margin && f.ci.high < s.k_max - margin;
    if (f.determined) seed_jackknife(curves, s, f);
    f.determined = f.ci.low > s.k_min + margin && f.ci.high < s.k_max - margin;
    f.extrapolated = extrapolated(d, k_hat);
    // The parameters at k̂.
    const AtK at = evaluate(d, k_hat, s, m.probits[m.best]);
    if (d.quantal() && at.probit.b > 0) f.threshold = -at.probit.a / at.probit.b, f.width = 1 / at.probit.b;
    else f.threshold = NAN, f.width = NAN;
    f.on_branch = d.on_branch;
    if (d.on_branch > 0) {
        for (int j = 0; j <= d.degree; ++j) f.branch.push_back(at.branch.p(j));
        f.sigma = at.branch.sigma;
        for (std::size_t j = 1; j < curves.size(); ++j)
            f.offsets.push_back(d.controls ? at.branch.p(d.degree + 1 + static_cast<int>(j)) - at.branch.p(d.degree + 1) : 0.0);
    }
    return f;
}

}  // namespace

double stand_probability(const TransitionFit& fit, double u) {
    if (std::isnan(fit.threshold)) return fit.standing > 0 && fit.slumped == 0 ? 1.0 : 0.0;
    return std::exp(log_phi_cdf((u - fit.threshold) / fit.width));
}

double slumped_branch(const TransitionFit& fit, double u) {
    double y = 0, power = 1;
    for (double beta : fit.branch) y += beta * power, power *= u - fit.centre;
    return y;
}

double mean_response(const TransitionFit& fit, double u) {
    const double p = stand_probability(fit, u);
    return (1 - p) * slumped_branch(fit, u) + p * fit.standing_slump;
}

std::vector<TransitionFit> fit_transition(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse,
                                          const TransitionSettings& settings) {
    check_response_curves(fine, coarse);
    if (!(settings.k_min < settings.k_max) || !(settings.stands_below > 0) || !(settings.min_width > 0))
        throw std::invalid_argument("bad transition model settings");
    std::vector<TransitionFit> out;
    for (const auto& c : coarse) out.push_back(fit_set({&fine, &c}, c.sf, settings));
    if (coarse.size() > 1) {
        std::vector<const ResponseCurve*> all{&fine};
        for (const auto& c : coarse) all.push_back(&c);
        out.push_back(fit_set(all, 0, settings));
    }
    return out;
}

}  // namespace demscale::stats
