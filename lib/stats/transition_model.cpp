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
};

struct Data {
    std::vector<WetRun> wet;
    std::vector<std::vector<double>> control;  // per curve; all empty: no offsets
    bool controls = false;
    int degree = 1;        // of the slumped branch
    double centre = 0;     // ū
    std::size_t standing = 0, slumped = 0, on_branch = 0;
    double standing_slump = 0;
    bool quantal() const { return standing > 0 && slumped > 0; }
};

Data gather(const std::vector<const ResponseCurve*>& curves, const TransitionSettings& s) {
    Data d;
    std::size_t fine_slumped_levels = 0;
    double fine_x = 0;
    std::size_t fine_n = 0;
    for (std::size_t c = 0; c < curves.size(); ++c)
        for (const auto& l : curves[c]->levels) {
            const bool pure = std::none_of(l.y.begin(), l.y.end(), [&](double y) { return y < s.stands_below; });
            for (double y : l.y) {
                const bool stands = y < s.stands_below;
                d.wet.push_back({l.x, std::log(curves[c]->sf), y, stands, pure, c});
                if (stands) d.standing++, d.standing_slump += y;
                else d.slumped++;
                if (pure) d.on_branch++;
                if (pure && c == 0) fine_x += l.x, fine_n++;
            }
            fine_slumped_levels += pure && c == 0;
        }
    if (d.standing > 0) d.standing_slump /= static_cast<double>(d.standing);
    d.centre = fine_n > 0 ? fine_x / static_cast<double>(fine_n) : 0.0;
    // The branch's shape comes from the fine levels alone, so that no shift of the coarse ones can
    // lend it a curvature (coarse levels that land on fine ones at some k would otherwise change
    // the polynomial's rank there).
    d.degree = fine_slumped_levels >= 3 ? 2 : fine_slumped_levels >= 2 ? 1 : 0;
    d.controls = std::all_of(curves.begin(), curves.end(), [](const auto* c) { return !c->control.y.empty(); });
    if (d.controls)
        for (const auto* c : curves) d.control.push_back(c->control.y);
    return d;
}

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

// The continuous part at one k: weighted least squares with the sd's of the wet and the dry runs
// re-estimated (their maximum likelihood), and its log-likelihood.
struct Branch {
    Eigen::VectorXd p;  // β₀, β₁[, β₂], then d per curve
    double sigma = 0, sigma_dry = 0, loglik = 0;
};

Branch fit_branch(const Data& d, double k) {
    const int nb = d.degree + 1, nd = d.controls ? static_cast<int>(d.control.size()) : 0;
    std::size_t rows = d.on_branch;
    for (const auto& c : d.control) rows += d.controls ? c.size() : 0;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), nb + nd);
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows));
    std::vector<bool> dry(rows, false);
    Eigen::Index i = 0;
    for (const auto& r : d.wet) {
        if (!r.on_branch) continue;
        const double v = r.x - k * r.log_sf - d.centre;
        for (int j = 0; j < nb; ++j) A(i, j) = std::pow(v, j);
        if (nd > 0 && r.curve > 0) A(i, nb + static_cast<int>(r.curve)) = 1, A(i, nb) = -1;
        y(i++) = r.y;
    }
    for (int c = 0; c < nd; ++c)
        for (double v : d.control[static_cast<std::size_t>(c)]) A(i, nb + c) = 1, dry[static_cast<std::size_t>(i)] = true, y(i++) = v;
    const double floor = 1e-4;  // of the fill height: noiseless data keep a finite likelihood
    Branch b;
    b.sigma = b.sigma_dry = 1;
    for (int it = 0; it < 8; ++it) {
        const double previous = b.sigma, previous_dry = b.sigma_dry;
        Eigen::VectorXd w(A.rows());
        for (Eigen::Index r = 0; r < A.rows(); ++r) w(r) = 1 / (dry[static_cast<std::size_t>(r)] ? b.sigma_dry : b.sigma);
        b.p = (w.asDiagonal() * A).completeOrthogonalDecomposition().solve(w.asDiagonal() * y);
        const Eigen::VectorXd res = y - A * b.p;
        double ss = 0, ss_dry = 0;
        std::size_t n = 0, n_dry = 0;
        for (Eigen::Index r = 0; r < A.rows(); ++r) (dry[static_cast<std::size_t>(r)] ? (ss_dry += res(r) * res(r), n_dry++) : (ss += res(r) * res(r), n++));
        b.sigma = std::max(floor, n ? std::sqrt(ss / static_cast<double>(n)) : floor);
        b.sigma_dry = std::max(floor, n_dry ? std::sqrt(ss_dry / static_cast<double>(n_dry)) : floor);
        b.loglik = 0;
        for (Eigen::Index r = 0; r < A.rows(); ++r) {
            const double s = dry[static_cast<std::size_t>(r)] ? b.sigma_dry : b.sigma;
            b.loglik += -0.5 * std::log(2 * M_PI * s * s) - 0.5 * res(r) * res(r) / (s * s);
        }
        if (std::abs(b.sigma - previous) < 1e-6 * b.sigma && std::abs(b.sigma_dry - previous_dry) < 1e-6 * b.sigma_dry) break;
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

TransitionFit fit_set(const std::vector<const ResponseCurve*>& curves, double sf, const TransitionSettings& s) {
    const Data d = gather(curves, s);
    TransitionFit f;
    f.sf = sf;
    f.standing = d.standing, f.slumped = d.slumped, f.quantal = d.quantal(), f.centre = d.centre;
    f.standing_slump = d.standing_slump;
    // The profile on a grid of 0.1, each point warm-started from its neighbour's probit.
    const double step = 0.1;
    const int n = static_cast<int>(std::ceil((s.k_max - s.k_min) / step));
    std::vector<double> ll(static_cast<std::size_t>(n) + 1);
    Probit warm;
    std::vector<Probit> probits;
    for (int i = 0; i <= n; ++i) {
        const double k = std::min(s.k_min + i * step, s.k_max);
        const AtK at = evaluate(d, k, s, warm);
        warm = at.probit;
        probits.push_back(warm);
        f.profile_k.push_back(k);
        ll[static_cast<std::size_t>(i)] = at.loglik;
    }
    const auto best = static_cast<std::size_t>(std::max_element(ll.begin(), ll.end()) - ll.begin());
    // Golden section between the best grid point's neighbours.
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    double a = f.profile_k[best > 0 ? best - 1 : 0], b = f.profile_k[std::min(best + 1, ll.size() - 1)];
    auto value = [&](double k) {  // warm-started from the nearest grid point's probit
        const auto i = static_cast<std::size_t>(std::clamp(std::lround((k - s.k_min) / step), 0L, static_cast<long>(n)));
        return evaluate(d, k, s, probits[i]).loglik;
    };
    double c = b - golden * (b - a), e = a + golden * (b - a), fc = value(c), fe = value(e);
    for (int it = 0; it < 30; ++it) {
        if (fc >= fe) b = e, e = c, fe = fc, c = b - golden * (b - a), fc = value(c);
        else a = c, c = e, fc = fe, e = a + golden * (b - a), fe = value(e);
    }
    double k_hat = 0.5 * (a + b), ll_hat = value(k_hat);
    if (ll_hat < ll[best]) k_hat = f.profile_k[best], ll_hat = ll[best];
    for (double v : ll) f.profile_deviance.push_back(std::max(0.0, 2 * (ll_hat - v)));
    const std::size_t wet_params = static_cast<std::size_t>(d.degree + 2) + (d.controls ? curves.size() - 1 : 0);
    f.cutoff = deviance_cutoff(d.on_branch, wet_params);
    // The interval: from k̂ outward to the first grid point beyond χ²₁, then bisection (the part of
    // {k : deviance ≤ χ²₁} that holds k̂).
    auto crossing = [&](int dir) -> double {
        int i = static_cast<int>(best);
        while (i + dir >= 0 && i + dir <= n && f.profile_deviance[static_cast<std::size_t>(i + dir)] <= f.cutoff) i += dir;
        if (i + dir < 0 || i + dir > n) return dir < 0 ? s.k_min : s.k_max;
        double inside = f.profile_k[static_cast<std::size_t>(i)];
        double outside = f.profile_k[static_cast<std::size_t>(i + dir)];
        for (int it = 0; it < 30; ++it) {
            const double mid = 0.5 * (inside + outside);
            (2 * (ll_hat - value(mid)) <= f.cutoff ? inside : outside) = mid;
        }
        return 0.5 * (inside + outside);
    };
    f.k = k_hat;
    f.ci = {crossing(-1), crossing(+1)};
    const double margin = step + 1e-9;
    f.determined = f.ci.low > s.k_min + margin && f.ci.high < s.k_max - margin;
    // The parameters at k̂.
    const AtK at = evaluate(d, k_hat, s, probits[best]);
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
