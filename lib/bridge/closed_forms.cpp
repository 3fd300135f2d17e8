#include "bridge/closed_forms.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <memory>
#include <numbers>

#include "bridge/mikami.hpp"

namespace demscale::bridge {

namespace {
constexpr double pi = std::numbers::pi;

struct Circle {
    double rho1, rho2;
};
// Fisher/Lian toroidal geometry: meridian radius from the gap, neck radius from the contact angle.
Circle circle_for(double beta, double theta, double d) {
    const double rho1 = (d + 1.0 - std::cos(beta)) / std::cos(beta + theta);
    return {rho1, std::sin(beta) - rho1 * (1.0 - std::sin(beta + theta))};
}
}  // namespace

double toroidal_volume(double beta, ContactAngle theta_angle, double d) {
    const double theta = theta_angle.radians();
    const auto [rho1, rho2] = circle_for(beta, theta, d);
    if (!(rho1 > 0)) return 0.0;
    const double a = rho1 + rho2;                       // r(z) = a − √(ρ₁² − z²)
    const double zc = d + 1.0 - std::cos(beta);         // contact height = ρ₁ cos(β + θ)
    const double root = std::sqrt(std::max(rho1 * rho1 - zc * zc, 0.0));
    const double i1 = 0.5 * (zc * root + rho1 * rho1 * std::asin(std::min(zc / rho1, 1.0)));
    const double revolution = pi * ((a * a + rho1 * rho1) * zc - zc * zc * zc / 3.0 - 2.0 * a * i1);
    const double cap = 1.0 - std::cos(beta);
    return 2.0 * (revolution - pi * cap * cap * (3.0 - cap) / 3.0);
}

ToroidalBridge toroidal_bridge(double vhat, ContactAngle theta_angle, double hhat) {
    const double theta = theta_angle.radians(), d = std::max(hhat, 0.0) / 2.0;
    ToroidalBridge out;
    struct P { double vhat; ContactAngle theta; double d; } p{vhat, theta_angle, d};
    gsl_function f{[](double beta, void* v) {
                       const P& q = *static_cast<P*>(v);
                       return toroidal_volume(beta, q.theta, q.d) - q.vhat;
                   },
                   &p};
    // β ∈ (0, π/2 − θ): volume grows with β; the neck must stay open (ρ₂ > 0).
    // At β → π/2 − θ the meridian circle becomes a line (ρ₁ → ∞) and the closed-form volume cancels
    // catastrophically; pendular bridges stay well below that limit.
    double lo = 1e-5, hi = pi / 2 - theta - 1e-2;  // β = 1e-5 holds V^ ~ 1e-20
    if (circle_for(lo, theta, d).rho2 <= 0) {  // smallest β whose neck is open, by bisection
        double closed = lo, open = hi;
        for (int i = 0; i < 200 && open - closed > 1e-15; ++i) {
            const double mid = 0.5 * (closed + open);
            (circle_for(mid, theta, d).rho2 > 0 ? open : closed) = mid;
        }
        lo = open;
    }
    if (!(f.function(lo, &p) < 0 && f.function(hi, &p) > 0)) return out;
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> s(gsl_root_fsolver_alloc(gsl_root_fsolver_brent),
                                                                          gsl_root_fsolver_free);
    gsl_root_fsolver_set(s.get(), &f, lo, hi);
    for (int i = 0; i < 200; ++i) {
        gsl_root_fsolver_iterate(s.get());
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s.get()), gsl_root_fsolver_x_upper(s.get()), 0, 1e-14) ==
            GSL_SUCCESS)
            break;
    }
    const double beta = gsl_root_fsolver_root(s.get());
    const auto [rho1, rho2] = circle_for(beta, theta, d);
    if (!(rho2 > 0)) return out;
    out = {beta, rho1, rho2, 0.5 * rho2 + 0.5 * rho2 * rho2 / rho1};  // gorge: r₀ − κr₀²/2 with κ = 1/ρ₂ − 1/ρ₁
    return out;
}

double willett_rupture_hhat(double vhat, ContactAngle theta) {
    return rupture_hhat(vhat, theta, RuptureLaw::willett2000);  // Eq. 15; refuses a V̂ that is not finite and > 0
}

double willett_full_fhat(double vhat, ContactAngle theta_angle, double hhat) {
    const double t = theta_angle.radians(), t2 = t * t, l = std::log(vhat), l2 = l * l, l3 = l2 * l;
    // Willett et al. 2000, appendix: coefficients quadratic in θ, polynomial in ln V*.
    const double f1 = (-0.44507 + 0.050832 * t - 1.1466 * t2) + (-0.1119 - 0.000411 * t - 0.1490 * t2) * l +
                      (-0.012101 - 0.0036456 * t - 0.01255 * t2) * l2 + (-0.0005 - 0.0003505 * t - 0.00029076 * t2) * l3;
    const double f2 = (1.9222 - 0.57473 * t - 1.2918 * t2) + (-0.0668 - 0.1201 * t - 0.22574 * t2) * l +
                      (-0.0013375 - 0.0068988 * t - 0.01137 * t2) * l2;
    const double f3 = (1.268 - 0.01396 * t - 0.23566 * t2) + (0.198 + 0.092 * t - 0.06418 * t2) * l +
                      (0.02232 + 0.02238 * t - 0.009853 * t2) * l2 + (0.0008585 + 0.001318 * t - 0.00053 * t2) * l3;
    const double f4 = (-0.010703 + 0.073776 * t - 0.34742 * t2) + (0.03345 + 0.04543 * t - 0.09056 * t2) * l +
                      (0.0018574 + 0.004456 * t - 0.006257 * t2) * l2;
    // S⁺ → 0 at contact: with f4 < 0 the inner exponential vanishes and F* → exp(f1).
    const double splus = std::max(0.5 * hhat / std::sqrt(vhat), 1e-300);
    const double ls = std::log(splus);
    return std::exp(f1 - f2 * std::exp(f3 * ls + f4 * ls * ls));
}

double willett_simple_fhat(double vhat, ContactAngle theta, double hhat) {
    const double splus = 0.5 * std::max(hhat, 0.0) / std::sqrt(vhat);
    return std::cos(theta.radians()) / (1.0 + 2.1 * splus + 10.0 * splus * splus);  // Eq. 12
}

}  // namespace demscale::bridge
