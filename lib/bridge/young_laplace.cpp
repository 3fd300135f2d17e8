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

// r, z, φ, π∫r² dz, and (sphere–plane only) the meniscus area 2π∫r ds: a fifth component would
// change the step control of the symmetric bridge, whose results stay as they were.
using State = std::array<double, 5>;

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
int meridian_area_rhs(double s, const double y[], double dyds[], void* params) {
    dyds[4] = 2 * pi * y[0];
    return meridian_rhs(s, y, dyds, params);
}

// Where the meniscus ends below: the mid-plane of two equal spheres (a neck, by symmetry), or a
// plate it meets at its own contact angle θ (rad) below a neck.
struct Lower {
    bool plate = false;
    double theta = 0;
};

// κ from the first integral at the neck (radius r₀, φ = 0) and at the sphere's contact line.
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

namespace {

// Where one step of the meridian leaves it: still going, at the event (pin it), or no shape.
enum class Step { on, reached, no_shape };

// Integrates the meridian from `start` (the neck: r₀, z = 0, φ = 0) with adaptive steps (rk8pd) until
// `step_end(prev, y, s)` says the event lies in the last step, then pins the event, e(y) = 0 with
// de/ds = `slope(y)`, by safeguarded Newton in arc length to |e| ≤ 1e-15·scale.
template <class StepEnd, class Event, class Slope>
std::optional<State> integrate_to(gsl_odeiv2_system& sys, const State& start, double h, const YoungLaplaceTolerance& tol, StepEnd step_end,
                                  Event event, Slope slope, double scale) {
    using StepPtr = std::unique_ptr<gsl_odeiv2_step, decltype(&gsl_odeiv2_step_free)>;
    using Control = std::unique_ptr<gsl_odeiv2_control, decltype(&gsl_odeiv2_control_free)>;
    using Evolve = std::unique_ptr<gsl_odeiv2_evolve, decltype(&gsl_odeiv2_evolve_free)>;
    StepPtr step(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, sys.dimension), gsl_odeiv2_step_free);
    Control control(gsl_odeiv2_control_y_new(tol.ode, tol.ode), gsl_odeiv2_control_free);
    Evolve evolve(gsl_odeiv2_evolve_alloc(sys.dimension), gsl_odeiv2_evolve_free);
    const double s_max = 20.0;  // a pendular meniscus between unit spheres is far shorter
    State prev = start, y = prev;
    double s_prev = 0, s = 0;
    for (int n = 0;; ++n) {
        prev = y;
        s_prev = s;
        if (n > 100000 || gsl_odeiv2_evolve_apply(evolve.get(), control.get(), step.get(), &sys, &s, s_max, &h, y.data()) !=
                              GSL_SUCCESS)
            return std::nullopt;
        const Step at = step_end(prev, y, s >= s_max);
        if (at == Step::reached) break;
        if (at == Step::no_shape) return std::nullopt;
    }
    Driver drv{gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 0.1 * (s - s_prev), tol.ode, tol.ode)};
    double lo = 0, hi = s - s_prev, delta = 0.5 * (lo + hi);
    State end = y;
    for (int it = 0; it < 60; ++it) {
        State trial = prev;
        double t = s_prev;
        gsl_odeiv2_driver_reset(drv.d);
        if (delta > 0 && gsl_odeiv2_driver_apply(drv.d, &t, s_prev + delta, trial.data()) != GSL_SUCCESS) return std::nullopt;
        const double residual = event(trial);
        end = trial;
        if (std::abs(residual) <= 1e-15 * scale) break;
        (residual > 0 ? hi : lo) = delta;
        const double rate = slope(trial);
        double next = rate > 1e-8 ? delta - residual / rate : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - delta) <= 1e-16 * (s_prev + delta)) break;
        delta = next;
    }
    return end;
}

// One side of the bridge for neck radius r₀ and filling angle β: from the neck up to the sphere's
// contact line (r = sin β); on a plate also from the neck down to the plate, the mirror image of
// the meridian above the neck up to where φ = π/2 − θ_plate (the ODE is symmetric about the neck).
std::optional<BridgeShape> integrate_meniscus(double beta, double r0, double theta, const Lower& lower, const YoungLaplaceTolerance& tol) {
    const double rc = std::sin(beta);
    if (!(beta > 0 && beta + theta < pi / 2 && r0 > 0 && r0 < rc)) return std::nullopt;
    double kappa = curvature_for(beta, r0, theta);
    if (!std::isfinite(kappa)) return std::nullopt;
    // The meniscus area (a fifth component) only on a plate: it would change the step control of
    // the symmetric bridge, whose results stay as they were.
    gsl_odeiv2_system sys{lower.plate ? meridian_area_rhs : meridian_rhs, nullptr, lower.plate ? 5u : 4u, &kappa};
    // The profile turned back toward the axis (a bulge) or curled over: no concave bridge here.
    auto bulges = [](const State& y, bool too_long) { return too_long || !(y[0] > 0) || y[2] <= 0 || y[2] >= pi; };
    const auto end = integrate_to(
        sys, State{r0, 0, 0, 0, 0}, 1e-3 * (rc - r0), tol,
        [&](const State&, const State& y, bool too_long) { return y[0] >= rc ? Step::reached : bulges(y, too_long) ? Step::no_shape : Step::on; },
        [&](const State& y) { return y[0] - rc; }, [](const State& y) { return std::sin(y[2]); }, rc);
    if (!end) return std::nullopt;

    BridgeShape b;
    b.neck_radius = r0;
    b.filling_angle = beta;
    b.curvature = kappa;
    b.half_gap = (*end)[1] - 1.0 + std::cos(beta);                     // z_c = 1 + d − cos β
    const double cap = 1.0 - std::cos(beta);
    b.volume = (*end)[3] - pi * cap * cap * (3.0 - cap) / 3.0;         // minus the sphere cap inside
    b.fhat_neck = r0 - 0.5 * kappa * r0 * r0;
    b.fhat_contact = (*end)[0] * std::cos((*end)[2]) - 0.5 * kappa * (*end)[0] * (*end)[0];
    b.contact_angle_error = std::abs((*end)[2] - (pi / 2 - beta - theta));
    if (!lower.plate) return b;

    const double phi_plate = pi / 2 - lower.theta;  // the mirror image of θ_plate − π/2 below the neck
    if (!(phi_plate > 0)) return std::nullopt;       // a plate at 90° or more has no neck above it
    // Near the start of the wide contact lines φ only just reaches the plate's angle at its
    // maximum, which a long step can pass over: the event is the first of φ = π/2 − θ_plate and
    // dφ/ds = 0, and a foot pinned where φ turned back short of the plate's angle has no shape.
    const auto rising = [&](const State& y) { return std::cos(y[2]) / y[0] - kappa; };  // dφ/ds
    const auto foot = integrate_to(
        sys, State{r0, 0, 0, 0, 0}, 1e-3 * (rc - r0), tol,
        [&](const State&, const State& y, bool too_long) {
            return y[2] >= phi_plate || rising(y) <= 0 ? Step::reached : bulges(y, too_long) ? Step::no_shape : Step::on;
        },
        [&](const State& y) { return std::max(y[2] - phi_plate, -rising(y)); },
        [&](const State& y) {
            if (y[2] - phi_plate >= -rising(y)) return rising(y);
            const double r = y[0], sin_phi = std::sin(y[2]);
            return (sin_phi * rising(y) * r + std::cos(y[2]) * sin_phi) / (r * r);  // d(−dφ/ds)/ds
        },
        1.0);
    if (!foot || (*foot)[2] < phi_plate - 1e-9) return std::nullopt;
    b.plate_radius = (*foot)[0];
    b.half_gap += (*foot)[1];            // the plate lies that far below the neck
    b.volume += (*foot)[3];
    b.meniscus_area = (*end)[4] + (*foot)[4];
    b.fhat_plate = (*foot)[0] * std::cos((*foot)[2]) - 0.5 * kappa * (*foot)[0] * (*foot)[0];
    return b;
}

// Both sides of a symmetric bridge: the volume of two halves.
std::optional<BridgeShape> integrate(double beta, double r0, double theta, const Lower& lower, const YoungLaplaceTolerance& tol) {
    auto b = integrate_meniscus(beta, r0, theta, lower, tol);
    if (b && !lower.plate) b->volume *= 2.0;
    return b;
}

}  // namespace

std::optional<BridgeShape> integrate_bridge(double beta, double r0, ContactAngle theta, const YoungLaplaceTolerance& tol) {
    return integrate(beta, r0, theta.radians(), Lower{}, tol);
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

// The filling angles with a shape for one neck can form more than one interval: on a plate,
// narrow contact lines just above the neck (the stable bridges) and wide ones, between which the
// meridian turns before it meets the plate at its angle; between spheres at large θ, where the
// widest contact lines bulge. The volume grows with β in each. A geometric scan up from the neck
// finds the first interval whose volumes reach V̂ (bisection pushes an interval's end when V̂ lies
// beyond the scan's last point in it); Brent's method solves there. On a plate only the first
// interval counts: a wide contact line belongs to another branch, and taking it would join the
// stable family to that branch where the first interval stops holding V̂.
template <class VolumeAt>
std::optional<BridgeShape> scanned_shape_with_volume(double r0, double vhat, double theta, const Lower& lower, const YoungLaplaceTolerance& tol,
                                                   double beta_min, double beta_limit, VolumeAt& volume_at) {
    constexpr int n = 48;
    const double first = beta_min * (1 + 1e-6), last = beta_limit - 1e-6, ratio = std::pow(last / first, 1.0 / (n - 1));
    std::optional<std::pair<double, double>> bracket;  // (lo, hi) in β, V(lo) < V̂ ≤ V(hi)
    std::optional<double> below;                        // the last β with a shape holding less than V̂
    double without = beta_min;                          // the last β without a shape
    bool had_shape = false;
    // Bisects between a β with a shape and one without (the interval's end), for V̂ on the far side.
    auto push = [&](double with, double none, bool want_less) {
        for (int j = 0; j < 50 && !bracket && std::abs(none - with) > 1e-13; ++j) {
            const double mid = 0.5 * (with + none);
            const auto vm = volume_at(mid);
            if (!vm) none = mid;
            else if ((*vm < vhat) == want_less) bracket = want_less ? std::pair{mid, with} : std::pair{with, mid};
            else with = mid;
        }
    };
    for (int i = 0; i < n && !bracket; ++i) {
        const double b = first * std::pow(ratio, i);
        const auto v = volume_at(b);
        had_shape = had_shape || v.has_value();
        if (v && *v >= vhat && below) bracket = {*below, b};
        else if (v && *v >= vhat) push(b, without, true);  // an interval starts above V̂: below it near its start?
        else if (v) below = b;
        else {
            if (below) push(*below, b, false);  // an interval ended below V̂: does it reach V̂ before its end?
            if (lower.plate && had_shape) break;  // on a plate only the first interval holds the stable bridges
            below.reset(), without = b;
        }
    }
    if (!bracket) return std::nullopt;
    auto beta = brent_root([&](double b) { auto v = volume_at(b); return v ? *v - vhat : NAN; }, bracket->first, bracket->second,
                           tol.root);
    if (!beta) return std::nullopt;
    return integrate(*beta, r0, theta, lower, tol);
}

// The constant-volume family: for a neck radius r₀, the filling angle that holds volume V̂.
std::optional<BridgeShape> shape_with_volume(double r0, double vhat, double theta, const Lower& lower, const YoungLaplaceTolerance& tol) {
    auto volume_at = [&](double beta) -> std::optional<double> {
        auto b = integrate(beta, r0, theta, lower, tol);
        return b ? std::optional(b->volume) : std::nullopt;
    };
    // Widest contact: β → π/2 − θ makes the meniscus meet the sphere vertically (φ_c → 0), where r
    // reaches sin β only tangentially; back off from that limit until the end point is well defined.
    const double beta_limit = pi / 2 - theta;
    const double beta_min = std::asin(r0);  // the neck is narrower than the contact line
    if (lower.plate) return scanned_shape_with_volume(r0, vhat, theta, lower, tol, beta_min, beta_limit, volume_at);
    // Between spheres: down from the widest contact line; where that finds nothing (large θ), the scan.
    const auto scanned = [&] { return scanned_shape_with_volume(r0, vhat, theta, lower, tol, beta_min, beta_limit, volume_at); };
    double beta_hi = beta_limit;
    std::optional<double> v_hi;
    for (double gap = 1e-6; gap < 0.5 && !v_hi; gap *= 4) {
        beta_hi = beta_limit - gap;
        if (!(r0 < std::sin(beta_hi))) return scanned();
        v_hi = volume_at(beta_hi);
    }
    if (!v_hi || *v_hi < vhat) return scanned();  // the widest contact bulges, or holds too little
    // Walk down from beta_hi to bracket the volume (V grows with β at fixed neck).
    double hi = beta_hi, lo = beta_hi;
    for (int i = 1; i <= 60; ++i) {
        lo = beta_min + (beta_hi - beta_min) * std::pow(0.5, i);
        const auto v = volume_at(lo);
        if (v && *v < vhat) break;
        if (v) hi = lo;
        if (i == 60) return scanned();
    }
    auto beta = brent_root([&](double b) { auto v = volume_at(b); return v ? *v - vhat : NAN; }, lo, hi, tol.root);
    if (!beta) return scanned();
    return integrate(*beta, r0, theta, lower, tol);
}

// Upper end of the family, by bisection: the widest neck that can still hold V̂ (on a plate, with
// the sphere still clear of it, gap ≥ −0.01 R, so that contact lies inside).
std::optional<double> widest_neck(double vhat, double theta, const Lower& lower, const YoungLaplaceTolerance& tol) {
    auto holds = [&](double r0) {
        const auto b = shape_with_volume(r0, vhat, theta, lower, tol);
        return b && (!lower.plate || b->half_gap >= -0.01);
    };
    double lo = 0, hi = std::sin(pi / 2 - theta);
    double probe = std::min(std::pow(2.0 * vhat / pi, 0.25), 0.5 * hi);  // toroidal contact estimate of β
    while (probe > 1e-12 && !holds(probe)) probe *= 0.5;
    if (probe <= 1e-12) return std::nullopt;
    lo = probe;
    for (int i = 0; i < 60 && hi - lo > 1e-10 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (holds(mid) ? lo : hi) = mid;
    }
    return lo;
}

// The fold of the gap along the family, r₀ ∈ (0, top]: coarse log scan, then Brent's minimiser of
// −gap. sides: 2 between spheres (the full gap is twice the half gap), 1 to a plate.
std::optional<Rupture> fold_of_family(double vhat, double theta, const Lower& lower, const YoungLaplaceTolerance& tol, double top) {
    auto half_gap = [&](double r0) { auto b = shape_with_volume(r0, vhat, theta, lower, tol); return b ? b->half_gap : -INFINITY; };
    const double sides = lower.plate ? 1.0 : 2.0;
    // The largest gap in (lo, hi) given a middle point whose gap exceeds both ends'.
    auto fold_between = [&](double lo, double d_lo, double mid, double d_mid, double hi, double d_hi) {
        gsl_function f;
        f.function = [](double x, void* p) { return -(*static_cast<decltype(half_gap)*>(p))(x); };
        f.params = &half_gap;
        std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> m(gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent),
                                                                                  gsl_min_fminimizer_free);
        if (gsl_min_fminimizer_set_with_values(m.get(), &f, mid, -d_mid, lo, -d_lo, hi, -d_hi) != GSL_SUCCESS)
            return Rupture{sides * d_mid, mid};
        for (int i = 0; i < 100; ++i) {
            if (gsl_min_fminimizer_iterate(m.get()) != GSL_SUCCESS) break;
            if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m.get()), gsl_min_fminimizer_x_upper(m.get()), 0.0, 1e-9) == GSL_SUCCESS)
                break;
        }
        return Rupture{-sides * gsl_min_fminimizer_f_minimum(m.get()), gsl_min_fminimizer_x_minimum(m.get())};
    };
    constexpr int n = 24;
    std::array<double, n> r{}, d{};
    int best = -1;
    for (int i = 0; i < n; ++i) r[i] = top * std::pow(1e-4, 1.0 - double(i) / (n - 1));
    if (!lower.plate) {
        for (int i = 0; i < n; ++i) {
            d[i] = half_gap(r[i]);
            if (std::isfinite(d[i]) && (best < 0 || d[i] > d[best])) best = i;
        }
    } else {
        // On a plate the family can break off: near rupture at θ > 0 the meridian turns (an
        // inflection) before it meets the plate at its angle, and for a range of necks no shape
        // holds V̂. The stable bridge stretches along the piece that reaches contact, from the
        // widest neck down; thinner necks beyond the break belong to another piece. When the gap
        // still grows where the piece ends, the bridge ruptures there; when it fell again between
        // the end and the thinnest scan point, the fold lies between them.
        d.fill(-INFINITY);
        int end = -1;  // the piece's thinnest scan point
        for (int i = n - 1; i >= 0 && (end < 0 || end == i + 1); --i) {
            d[i] = half_gap(r[i]);
            if (!std::isfinite(d[i])) continue;
            end = i;
            if (best < 0 || d[i] > d[best]) best = i;
        }
        if (best >= 0 && best == end && end > 0) {
            double with = r[end], without = r[end - 1], gap = d[end];
            for (int i = 0; i < 50 && with - without > 1e-12 * with; ++i) {
                const double mid = 0.5 * (with + without);
                const double g = half_gap(mid);
                if (std::isfinite(g)) with = mid, gap = g;
                else without = mid;
            }
            if (gap >= d[end] || end == n - 1) return Rupture{gap, with, true};
            return fold_between(with, gap, r[end], d[end], r[end + 1], d[end + 1]);
        }
    }
    if (best < 0) return std::nullopt;
    if (best == 0 || best == n - 1) return Rupture{sides * d[best], r[best]};  // fold at the scan's edge
    return fold_between(r[best - 1], d[best - 1], r[best], d[best], r[best + 1], d[best + 1]);
}

Lower lower_of(const std::optional<ContactAngle>& plate) { return plate ? Lower{true, plate->radians()} : Lower{}; }

// Symmetry breaking. Without the mirror symmetry a bridge between equal spheres at half gap d is
// a meridian shot from the lower sphere's contact line (filling angle β₁, curvature κ) that must
// meet the upper sphere at the contact angle and hold V̂: two residuals in two unknowns. Along the
// symmetric family their Jacobian is singular at the fold (a symmetric null vector) and where an
// antisymmetric one appears: there the constant-volume bridge stops being stable against liquid
// moving to one sphere. Residuals (g, V) of the shot from (β₁, κ); g measured where the meridian
// meets the upper sphere (its angle mismatch) or, at small θ where it meets the sphere almost
// tangentially, where it reaches the contact angle (its distance inside the sphere).
std::optional<std::array<double, 2>> unmirrored_residuals(double beta1, double kappa, double d, double theta, bool by_angle,
                                                         const YoungLaplaceTolerance& tol) {
    gsl_odeiv2_system sys{meridian_rhs, nullptr, 4u, &kappa};
    const double c = 1 + d;  // the upper sphere's centre; the lower one's is at −c
    const State start{std::sin(beta1), -c + std::cos(beta1), -(pi / 2 - beta1 - theta), 0, 0};  // the mirror of the upper line
    const auto inside = [c](const State& y) { return 1 - (y[0] * y[0] + (y[1] - c) * (y[1] - c)); };
    const auto inside_rate = [c](const State& y) { return -2 * (y[0] * std::sin(y[2]) + (y[1] - c) * std::cos(y[2])); };
    const auto angle = [&](const State& y) { return y[2] + std::atan2(y[0], c - y[1]) + theta - pi / 2; };
    const auto angle_rate = [&](const State& y) {
        const double w = c - y[1];
        return std::cos(y[2]) / y[0] - kappa + (w * std::sin(y[2]) + y[0] * std::cos(y[2])) / (y[0] * y[0] + w * w);
    };
    const auto stop = [&](const State& y) { return by_angle ? angle(y) : inside(y); };
    const auto end = integrate_to(
        sys, start, 1e-4, tol,
        [&](const State&, const State& y, bool too_long) { return stop(y) >= 0 ? Step::reached : too_long || !(y[0] > 0) ? Step::no_shape : Step::on; },
        stop, [&](const State& y) { return by_angle ? angle_rate(y) : inside_rate(y); }, 1.0);
    if (!end) return std::nullopt;
    const auto cap = [](double b) { const double h = 1 - std::cos(b); return pi * h * h * (3 - h) / 3; };
    const double beta2 = std::atan2((*end)[0], c - (*end)[1]);
    return std::array{by_angle ? inside(*end) : angle(*end), (*end)[3] - cap(beta1) - cap(beta2)};
}

// det ∂(g, V)/∂(β₁, κ) at a symmetric shape, by central differences.
std::optional<double> unmirrored_determinant(const BridgeShape& b, double theta, bool by_angle, const YoungLaplaceTolerance& tol) {
    const double db = 1e-6 * b.filling_angle, dk = 1e-6 * std::max(1.0, std::abs(b.curvature));
    const auto bp = unmirrored_residuals(b.filling_angle + db, b.curvature, b.half_gap, theta, by_angle, tol);
    const auto bm = unmirrored_residuals(b.filling_angle - db, b.curvature, b.half_gap, theta, by_angle, tol);
    const auto kp = unmirrored_residuals(b.filling_angle, b.curvature + dk, b.half_gap, theta, by_angle, tol);
    const auto km = unmirrored_residuals(b.filling_angle, b.curvature - dk, b.half_gap, theta, by_angle, tol);
    if (!bp || !bm || !kp || !km) return std::nullopt;
    const double gb = ((*bp)[0] - (*bm)[0]) / (2 * db), vb = ((*bp)[1] - (*bm)[1]) / (2 * db);
    const double gk = ((*kp)[0] - (*km)[0]) / (2 * dk), vk = ((*kp)[1] - (*km)[1]) / (2 * dk);
    return gb * vk - gk * vb;
}

}  // namespace

SymmetryCheck YoungLaplaceBridge::check_symmetry(Residual residual) const {
    // The determinant keeps the sign it has near contact (a stable bridge) up to the fold unless an
    // antisymmetric mode appears first: scan towards the fold (1 − x shrinking geometrically),
    // then bisect to 1e-8 of the fold gap.
    const double fold = rupture_->hhat;
    const auto det_at = [&](double x) -> std::optional<double> {
        const auto r = solve_on_family(x * fold);
        return r.ok() ? unmirrored_determinant(r.shape, theta_.radians(), residual == Residual::by_angle, tol_) : std::nullopt;
    };
    const auto reference = det_at(0.1);
    if (!reference || *reference == 0) return {SymmetryStatus::not_determined, 0};
    double stable = 0.1;
    for (double rest = 0.6; rest > 1e-6; rest *= 0.6) {
        const double x = 1 - rest;
        const auto det = det_at(x);
        if (!det) return {SymmetryStatus::not_determined, 0};
        if ((*det > 0) == (*reference > 0)) {
            stable = x;
            continue;
        }
        double broken = x;
        while (broken - stable > 1e-8) {
            const double mid = 0.5 * (stable + broken);
            const auto dm = det_at(mid);
            if (!dm) return {SymmetryStatus::not_determined, 0};
            ((*dm > 0) == (*reference > 0) ? stable : broken) = mid;
        }
        return {SymmetryStatus::breaks, stable * fold};
    }
    return {SymmetryStatus::holds_to_fold, fold};
}

std::optional<Rupture> young_laplace_rupture(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol) {
    require_positive(vhat, "vhat");
    const auto top = widest_neck(vhat, theta.radians(), Lower{}, tol);
    return top ? fold_of_family(vhat, theta.radians(), Lower{}, tol, *top) : std::nullopt;
}

YoungLaplaceBridge::YoungLaplaceBridge(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol,
                                       std::optional<ContactAngle> theta_plate)
    : vhat_(vhat), theta_(theta), tol_(tol), plate_(theta_plate) {
    require_positive(vhat, "vhat");
    const Lower lower = lower_of(plate_);
    widest_neck_ = widest_neck(vhat, theta.radians(), lower, tol);
    if (widest_neck_) rupture_ = fold_of_family(vhat, theta.radians(), lower, tol, *widest_neck_);
    if (family_ok() && !plate_)  // a plate is its own mirror: nothing to break
        symmetry_ = check_symmetry(theta.degrees() < 20 ? Residual::by_angle : Residual::at_sphere);
    if (!family_ok())
        family_message_ = "no concave bridge of V^ = " + format_number(vhat) + " at theta = " + format_number(theta.degrees()) +
                          (plate_ ? " deg (sphere), " + format_number(plate_->degrees()) + " deg (plate)" : " deg") +
                          " (constant-volume family not traced)";
}

YoungLaplaceBridge YoungLaplaceBridge::sphere_plane(double vhat, ContactAngle theta, ContactAngle theta_plate,
                                                   const YoungLaplaceTolerance& tol) {
    return YoungLaplaceBridge(vhat, theta, tol, theta_plate);
}

double YoungLaplaceBridge::hhat_rupture() const {
    if (!rupture_) return 0.0;
    return symmetry_.status == SymmetryStatus::breaks ? symmetry_.hhat : rupture_->hhat;
}

YoungLaplaceResult YoungLaplaceBridge::solve(double hhat) const {
    require_finite(hhat, "hhat");
    if (family_ok() && hhat > hhat_rupture() && hhat <= rupture_->hhat) {
        YoungLaplaceResult res;
        res.status = YoungLaplaceStatus::above_rupture;
        res.hhat_rupture = hhat_rupture();
        res.message = "h^ = " + format_number(hhat) + " is beyond rupture (h^_c = " + format_number(hhat_rupture()) +
                      ": the symmetric bridge breaks symmetry there, before its fold at " + format_number(rupture_->hhat) + ")";
        return res;
    }
    return solve_on_family(hhat);
}

YoungLaplaceResult YoungLaplaceBridge::solve_on_family(double hhat) const {
    require_finite(hhat, "hhat");
    YoungLaplaceResult res;
    if (!family_ok()) {  // no concave bridge of this volume at this angle: the input is out of scope
        res.status = YoungLaplaceStatus::outside_scope;
        res.message = family_message_;
        return res;
    }
    res.hhat_rupture = hhat_rupture();
    if (hhat < 0) {
        res.status = YoungLaplaceStatus::outside_scope;
        res.message = "overlapping spheres (h^ < 0) are outside the solver's scope; use h^ = 0";
        return res;
    }
    if (hhat > rupture_->hhat) {
        res.status = YoungLaplaceStatus::above_rupture;
        res.message = "h^ = " + format_number(hhat) + " is beyond rupture (h^_c = " + format_number(hhat_rupture()) + ")";
        return res;
    }
    const Lower lower = lower_of(plate_);
    auto gap_error = [&](double r0) {
        auto b = shape_with_volume(r0, vhat_, theta_.radians(), lower, tol_);
        return b ? b->half_gap - (lower.plate ? hhat : 0.5 * hhat) : NAN;
    };
    // The stable branch: wide necks, from the fold up to the widest neck; the gap falls along it.
    const double hi = *widest_neck_;
    double lo = rupture_->neck_radius;
    // Where a plate's piece breaks off, its end lies within the bisection's 1e-12 of necks without
    // a shape: step inside until the end has one (the gap there is h^_c to ~1e-9).
    for (double step = 1e-11; !std::isfinite(gap_error(lo)) && step < 1e-3; step *= 10) lo = rupture_->neck_radius * (1 + step);
    if (!(gap_error(hi) <= 0)) {
        res.status = YoungLaplaceStatus::outside_scope;
        res.message = "no concave bridge at h^ = " + format_number(hhat) + " (the meniscus would bulge: V^ = " +
                      format_number(vhat_) + ", theta = " + format_number(theta_.degrees()) + " deg)";
        return res;
    }
    std::optional<double> r0 = lo;
    if (!(gap_error(lo) < 0)) r0 = brent_root(gap_error, lo, hi, tol_.root);  // else: at the fold itself
    const auto shape = r0 ? shape_with_volume(*r0, vhat_, theta_.radians(), lower, tol_) : std::nullopt;
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
