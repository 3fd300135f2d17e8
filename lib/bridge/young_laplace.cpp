#include "bridge/young_laplace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>
#include <memory>
#include <numbers>

#include "core/input_error.hpp"

namespace demscale::bridge {

namespace {

constexpr double pi = std::numbers::pi;
// GSL reports failures through return codes here; its default handler would abort the program.
const bool gsl_quiet = [] { gsl_set_error_handler_off(); return true; }();

using State = std::array<double, 4>;  // r, z, φ, π∫r² dz

int meridian_rhs(double, const double y[], double dyds[], void* params) {
    const double kappa = *static_cast<const double*>(params);
    const double r = y[0], phi = y[2];
    if (!(r > 0)) return GSL_EBADFUNC;
    dyds[0] = std::sin(phi);
    dyds[1] = std::cos(phi);
    dyds[2] = std::cos(phi) / r - kappa;
    dyds[3] = pi * r * r * std::cos(phi);
    return GSL_SUCCESS;
}

// κ from the first integral at neck and contact line (see header).
double curvature_for(double beta, double r0, double theta) {
    const double sb = std::sin(beta);
    return 2.0 * (sb * std::sin(beta + theta) - r0) / ((sb - r0) * (sb + r0));
}

struct Driver {  // RAII over a GSL odeiv2 driver
    gsl_odeiv2_driver* d;
    ~Driver() { gsl_odeiv2_driver_free(d); }
};

// Brent root of f on [lo, hi] (f(lo), f(hi) of opposite signs). nullopt if GSL fails.
std::optional<double> brent_root(const std::function<double(double)>& f, double lo, double hi, double rel_tol) {
    gsl_function gf;
    gf.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
    gf.params = const_cast<std::function<double(double)>*>(&f);
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> s(gsl_root_fsolver_alloc(gsl_root_fsolver_brent),
                                                                          gsl_root_fsolver_free);
    if (gsl_root_fsolver_set(s.get(), &gf, lo, hi) != GSL_SUCCESS) return std::nullopt;
    for (int i = 0; i < 200; ++i) {
        if (gsl_root_fsolver_iterate(s.get()) != GSL_SUCCESS) return std::nullopt;
        const double a = gsl_root_fsolver_x_lower(s.get()), b = gsl_root_fsolver_x_upper(s.get());
        if (gsl_root_test_interval(a, b, 1e-300, rel_tol) == GSL_SUCCESS) return gsl_root_fsolver_root(s.get());
    }
    return std::nullopt;
}

}  // namespace

std::optional<BridgeShape> integrate_bridge(double beta, double r0, ContactAngle theta_angle,
                                            const YoungLaplaceTolerance& tol) {
    const double theta = theta_angle.radians();
    const double rc = std::sin(beta);
    if (!(beta > 0 && beta + theta < pi / 2 && r0 > 0 && r0 < rc)) return std::nullopt;
    double kappa = curvature_for(beta, r0, theta);
    if (!std::isfinite(kappa)) return std::nullopt;

    gsl_odeiv2_system sys{meridian_rhs, nullptr, 4, &kappa};
    // Adaptive steps (rk8pd) until r passes the contact radius; then pin the end point by
    // safeguarded Newton in arc length from the last step.
    using Step = std::unique_ptr<gsl_odeiv2_step, decltype(&gsl_odeiv2_step_free)>;
    using Control = std::unique_ptr<gsl_odeiv2_control, decltype(&gsl_odeiv2_control_free)>;
    using Evolve = std::unique_ptr<gsl_odeiv2_evolve, decltype(&gsl_odeiv2_evolve_free)>;
    Step step(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 4), gsl_odeiv2_step_free);
    Control control(gsl_odeiv2_control_y_new(tol.ode, tol.ode), gsl_odeiv2_control_free);
    Evolve evolve(gsl_odeiv2_evolve_alloc(4), gsl_odeiv2_evolve_free);
    const double s_max = 20.0;  // a pendular meniscus between unit spheres is far shorter
    State prev{r0, 0, 0, 0}, y = prev;
    double s_prev = 0, s = 0, h = 1e-3 * (rc - r0);
    for (int n = 0;; ++n) {
        prev = y;
        s_prev = s;
        if (n > 100000 || gsl_odeiv2_evolve_apply(evolve.get(), control.get(), step.get(), &sys, &s, s_max, &h, y.data()) !=
                              GSL_SUCCESS)
            return std::nullopt;
        if (y[0] >= rc) break;
        // The profile turned back toward the axis (a bulge) or curled over: no concave bridge here.
        if (s >= s_max || !(y[0] > 0) || y[2] <= 0 || y[2] >= pi) return std::nullopt;
    }
    Driver drv{gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 0.1 * (s - s_prev), tol.ode, tol.ode)};
    double lo = 0, hi = s - s_prev, delta = 0.5 * (lo + hi);
    State end = y;
    for (int it = 0; it < 60; ++it) {
        State trial = prev;
        double t = s_prev;
        gsl_odeiv2_driver_reset(drv.d);
        if (delta > 0 && gsl_odeiv2_driver_apply(drv.d, &t, s_prev + delta, trial.data()) != GSL_SUCCESS) return std::nullopt;
        const double residual = trial[0] - rc;
        end = trial;
        if (std::abs(residual) <= 1e-15 * rc) break;
        (residual > 0 ? hi : lo) = delta;
        const double slope = std::sin(trial[2]);
        double next = slope > 1e-8 ? delta - residual / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - delta) <= 1e-16 * (s_prev + delta)) break;
        delta = next;
    }

    BridgeShape b;
    b.neck_radius = r0;
    b.filling_angle = beta;
    b.curvature = kappa;
    b.half_gap = end[1] - 1.0 + std::cos(beta);                        // z_c = 1 + d − cos β
    const double cap = 1.0 - std::cos(beta);
    b.volume = 2.0 * (end[3] - pi * cap * cap * (3.0 - cap) / 3.0);   // minus the sphere caps inside
    b.fhat_neck = r0 - 0.5 * kappa * r0 * r0;
    b.fhat_contact = end[0] * std::cos(end[2]) - 0.5 * kappa * end[0] * end[0];
    b.contact_angle_error = std::abs(end[2] - (pi / 2 - beta - theta));
    return b;
}

std::pair<double, double> bridge_by_quadrature(double beta, double r0, ContactAngle theta_angle) {
    const double theta = theta_angle.radians();
    const double rc = std::sin(beta);
    const double kappa = curvature_for(beta, r0, theta);
    const double g = r0 - 0.5 * kappa * r0 * r0;  // first integral
    // r = r0 + (rc − r0) t² removes the 1/√ singularity of dz/dr = c/√(1 − c²) at the neck.
    struct P { double r0, span, g, kappa; int power; } p{r0, rc - r0, g, kappa, 0};
    auto integrand = [](double t, void* v) {
        const P& q = *static_cast<P*>(v);
        const double r = q.r0 + q.span * t * t;
        const double c = q.g / r + 0.5 * q.kappa * r;
        const double dzdr = c / std::sqrt(std::max((1 - c) * (1 + c), 1e-300));
        return (q.power == 0 ? 1.0 : pi * r * r) * dzdr * 2.0 * q.span * t;
    };
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> w(
        gsl_integration_workspace_alloc(2000), gsl_integration_workspace_free);
    gsl_function f{integrand, &p};
    double z = 0, v = 0, err = 0;
    gsl_integration_qags(&f, 0.0, 1.0, 1e-14, 1e-13, 2000, w.get(), &z, &err);
    p.power = 2;
    gsl_integration_qags(&f, 0.0, 1.0, 1e-14, 1e-13, 2000, w.get(), &v, &err);
    const double cap = 1.0 - std::cos(beta);
    return {z - 1.0 + std::cos(beta), 2.0 * (v - pi * cap * cap * (3.0 - cap) / 3.0)};
}

namespace {

// The constant-volume family: for a neck radius r₀, the filling angle that holds volume V̂.
std::optional<BridgeShape> shape_with_volume(double r0, double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol) {
    auto volume_at = [&](double beta) -> std::optional<double> {
        auto b = integrate_bridge(beta, r0, theta, tol);
        return b ? std::optional(b->volume) : std::nullopt;
    };
    // Widest contact: β → π/2 − θ makes the meniscus meet the sphere vertically (φ_c → 0), where r
    // reaches sin β only tangentially; back off from that limit until the end point is well defined.
    const double beta_limit = pi / 2 - theta.radians();
    const double beta_min = std::asin(r0);
    double beta_hi = beta_limit;
    std::optional<double> v_hi;
    for (double gap = 1e-6; gap < 0.5 && !v_hi; gap *= 4) {
        beta_hi = beta_limit - gap;
        if (!(r0 < std::sin(beta_hi))) return std::nullopt;
        v_hi = volume_at(beta_hi);
    }
    if (!v_hi || *v_hi < vhat) return std::nullopt;  // even the widest contact holds too little
    // Walk down from beta_hi to bracket the volume (V grows with β at fixed neck).
    double hi = beta_hi, lo = beta_hi;
    for (int i = 1; i <= 60; ++i) {
        lo = beta_min + (beta_hi - beta_min) * std::pow(0.5, i);
        const auto v = volume_at(lo);
        if (v && *v < vhat) break;
        if (v) hi = lo;
        if (i == 60) return std::nullopt;
    }
    auto beta = brent_root([&](double b) { auto v = volume_at(b); return v ? *v - vhat : NAN; }, lo, hi, tol.root);
    if (!beta) return std::nullopt;
    return integrate_bridge(*beta, r0, theta, tol);
}

// Largest neck radius that can still hold V̂ (upper end of the family), by bisection.
std::optional<double> widest_neck(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol) {
    double lo = 0, hi = std::sin(pi / 2 - theta.radians());
    double probe = std::min(std::pow(2.0 * vhat / pi, 0.25), 0.5 * hi);  // toroidal contact estimate of β
    while (probe > 1e-12 && !shape_with_volume(probe, vhat, theta, tol)) probe *= 0.5;
    if (probe <= 1e-12) return std::nullopt;
    lo = probe;
    for (int i = 0; i < 60 && hi - lo > 1e-10 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (shape_with_volume(mid, vhat, theta, tol) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace

namespace {

// The fold of d(r₀) on r₀ ∈ (0, top]: coarse log scan, then Brent's minimiser of −d.
std::optional<Rupture> fold_of_family(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol, double top) {
    auto half_gap = [&](double r0) { auto b = shape_with_volume(r0, vhat, theta, tol); return b ? b->half_gap : -INFINITY; };
    constexpr int n = 24;
    std::array<double, n> r{}, d{};
    int best = -1;
    for (int i = 0; i < n; ++i) {
        r[i] = top * std::pow(1e-4, 1.0 - double(i) / (n - 1));
        d[i] = half_gap(r[i]);
        if (std::isfinite(d[i]) && (best < 0 || d[i] > d[best])) best = i;
    }
    if (best < 0) return std::nullopt;
    if (best == 0 || best == n - 1) return Rupture{2.0 * d[best], r[best]};  // fold at the scan's edge
    gsl_function f;
    f.function = [](double x, void* p) { return -(*static_cast<decltype(half_gap)*>(p))(x); };
    f.params = &half_gap;
    std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> m(gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent),
                                                                              gsl_min_fminimizer_free);
    if (gsl_min_fminimizer_set_with_values(m.get(), &f, r[best], -d[best], r[best - 1], -d[best - 1], r[best + 1],
                                           -d[best + 1]) != GSL_SUCCESS)
        return Rupture{2.0 * d[best], r[best]};
    for (int i = 0; i < 100; ++i) {
        if (gsl_min_fminimizer_iterate(m.get()) != GSL_SUCCESS) break;
        if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m.get()), gsl_min_fminimizer_x_upper(m.get()), 0.0, 1e-9) ==
            GSL_SUCCESS)
            break;
    }
    return Rupture{-2.0 * gsl_min_fminimizer_f_minimum(m.get()), gsl_min_fminimizer_x_minimum(m.get())};
}

}  // namespace

std::optional<Rupture> young_laplace_rupture(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol) {
    require_positive(vhat, "vhat");
    const auto top = widest_neck(vhat, theta, tol);
    return top ? fold_of_family(vhat, theta, tol, *top) : std::nullopt;
}

YoungLaplaceBridge::YoungLaplaceBridge(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol)
    : vhat_(vhat), theta_(theta), tol_(tol) {
    require_positive(vhat, "vhat");
    widest_neck_ = widest_neck(vhat, theta, tol);
    if (widest_neck_) rupture_ = fold_of_family(vhat, theta, tol, *widest_neck_);
    if (!family_ok())
        family_message_ = "no concave bridge of V^ = " + format_number(vhat) + " at theta = " +
                          format_number(theta.degrees()) + " deg (constant-volume family not traced)";
}

YoungLaplaceResult YoungLaplaceBridge::solve(double hhat) const {
    require_finite(hhat, "hhat");
    YoungLaplaceResult res;
    if (!family_ok()) {  // no concave bridge of this volume at this angle: the input is out of scope
        res.status = YoungLaplaceStatus::outside_scope;
        res.message = family_message_;
        return res;
    }
    res.hhat_rupture = rupture_->hhat;
    if (hhat < 0) {
        res.status = YoungLaplaceStatus::outside_scope;
        res.message = "overlapping spheres (h^ < 0) are outside the solver's scope; use h^ = 0";
        return res;
    }
    if (hhat > rupture_->hhat) {
        res.status = YoungLaplaceStatus::above_rupture;
        res.message = "h^ = " + format_number(hhat) + " is beyond rupture (h^_c = " + format_number(rupture_->hhat) + ")";
        return res;
    }
    auto gap_error = [&](double r0) {
        auto b = shape_with_volume(r0, vhat_, theta_, tol_);
        return b ? b->half_gap - 0.5 * hhat : NAN;
    };
    // The stable branch: wide necks, from the fold up to the widest neck; the gap falls along it.
    const double lo = rupture_->neck_radius, hi = *widest_neck_;
    if (!(gap_error(hi) <= 0)) {
        res.status = YoungLaplaceStatus::outside_scope;
        res.message = "no concave bridge at h^ = " + format_number(hhat) + " (the meniscus would bulge: V^ = " +
                      format_number(vhat_) + ", theta = " + format_number(theta_.degrees()) + " deg)";
        return res;
    }
    std::optional<double> r0 = lo;
    if (!(gap_error(lo) < 0)) r0 = brent_root(gap_error, lo, hi, tol_.root);  // else: at the fold itself
    const auto shape = r0 ? shape_with_volume(*r0, vhat_, theta_, tol_) : std::nullopt;
    if (!shape) {
        res.message = "root finding for the neck radius did not converge";
        return res;
    }
    res.shape = *shape;
    res.status = YoungLaplaceStatus::ok;
    return res;
}

YoungLaplaceResult solve_young_laplace(double vhat, ContactAngle theta, double hhat, const YoungLaplaceTolerance& tol) {
    return YoungLaplaceBridge(vhat, theta, tol).solve(hhat);
}

}  // namespace demscale::bridge
