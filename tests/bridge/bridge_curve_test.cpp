// The DEM's bridge curves against independent routes: the tabulated exact curve against the exact
// solver between its nodes, and its work to rupture against an adaptive quadrature of the solver's
// forces; Willett's tabulated fit against the closed form; the curve sources' declarations.
#include <catch2/catch.hpp>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <set>

#include "bridge/bridge_curve.hpp"
#include "bridge/closed_forms.hpp"
#include "bridge/curve_sources.hpp"
#include "bridge/young_laplace.hpp"

using namespace demscale;
using namespace demscale::bridge;

namespace {
ContactAngle deg(double d) { return ContactAngle{Degrees{d}}; }

YoungLaplaceBridge family(double vhat, double theta, BridgeGeometry g) {
    return g == BridgeGeometry::sphere_sphere ? YoungLaplaceBridge(vhat, deg(theta)) : YoungLaplaceBridge::sphere_plane(vhat, deg(theta), deg(theta));
}

// ∫ F̂ dĥ from a to b by GSL's adaptive QAGS on the exact solver itself.
double solver_work(const YoungLaplaceBridge& b, double from, double to) {
    std::function<double(double)> f = [&](double h) {
        const auto r = b.solve(std::min(h, b.hhat_rupture()));
        REQUIRE(r.ok());
        return r.shape.fhat_neck;
    };
    gsl_function gf{[](double x, void* p) { return (*static_cast<std::function<double(double)>*>(p))(x); }, &f};
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> w(gsl_integration_workspace_alloc(200),
                                                                                          gsl_integration_workspace_free);
    double result = 0, error = 0;
    gsl_integration_qags(&gf, from, to, 0, 1e-9, 200, w.get(), &result, &error);
    return result;
}
}  // namespace

TEST_CASE("The tabulated exact curve follows the exact solver between its nodes", "[bridge][curve]") {
    for (auto g : {BridgeGeometry::sphere_sphere, BridgeGeometry::sphere_wall})
        for (double vhat : {1e-4, 0.05544})
            for (double theta : {0.0, 40.0}) {
                INFO(to_string(g) << ", V^ = " << vhat << ", theta = " << theta);
                const auto exact = family(vhat, theta, g);
                const auto curve = BridgeCurve::exact(vhat, deg(theta), g);
                CHECK(curve.tabulated());
                CHECK(curve.hhat_rupture() == exact.hhat_rupture());
                CHECK(curve.force_scale() == Approx(2 * M_PI).epsilon(1e-15));
                double worst = 0;
                // Midway between nodes in the gap coordinate, where a cubic is least accurate.
                const int n = BridgeCurve::default_gap_points;
                for (int i = 0; i + 1 < n; i += 3) {
                    const double x = BridgeTable::gap_fraction((i + 0.5) / (n - 1));
                    const auto r = exact.solve(x * exact.hhat_rupture());
                    REQUIRE(r.ok());
                    worst = std::max(worst, std::abs(curve.fhat(x * exact.hhat_rupture()) / r.shape.fhat_neck - 1));
                }
                CHECK(worst < 5e-4);
                CHECK(curve.fhat(-0.01) == curve.fhat(0.0));  // an overlap counts as contact
                CHECK(curve.fhat(exact.hhat_rupture() * (1 + 1e-9)) == 0.0);
            }
}

TEST_CASE("The tabulated curve's work to rupture matches a quadrature of the exact solver", "[bridge][curve][slow]") {
    for (auto g : {BridgeGeometry::sphere_sphere, BridgeGeometry::sphere_wall}) {
        const double vhat = 0.05544, theta = 20;
        INFO(to_string(g));
        const auto exact = family(vhat, theta, g);
        const auto curve = BridgeCurve::exact(vhat, deg(theta), g);
        const double hc = exact.hhat_rupture();
        for (double x : {0.0, 0.37, 0.9}) {
            INFO("h^/h^_c = " << x);
            CHECK(curve.work_to_rupture(x * hc) == Approx(solver_work(exact, x * hc, hc)).epsilon(2e-5));
        }
        CHECK(curve.work_to_rupture(-0.01) == Approx(curve.work_to_rupture(0) + 0.01 * curve.fhat(0)).epsilon(1e-13));
        CHECK(curve.work_to_rupture(hc) == 0.0);
    }
}

TEST_CASE("A Mikami fit as a curve is the fit itself", "[bridge][curve]") {
    const auto k = mikami_coefficients(0.05544, deg(20));
    const BridgeCurve curve = k;
    CHECK_FALSE(curve.tabulated());
    CHECK(curve.hhat_rupture() == k.hhat_rupture);
    CHECK(curve.force_scale() == k.force_scale);
    for (double h : {-0.01, 0.0, 0.1, 0.3, 0.5}) {
        CHECK(curve.fhat(h) == mikami_fhat(k, h));
        CHECK(curve.work_to_rupture(h) == mikami_work_to_rupture(k, h));
    }
}

TEST_CASE("Exact sphere-plane columns solve at every node for theta 0-40 deg and V^ 1e-5-0.2", "[bridge][sphere-plane][curve][slow]") {
    for (double vhat : {1e-5, 1e-3, 0.05544, 0.2})
        for (double theta : {0.0, 10.0, 20.0, 30.0, 40.0}) {
            INFO("V^ = " << vhat << ", theta = " << theta);
            CHECK_NOTHROW(BridgeCurve::exact(vhat, deg(theta), BridgeGeometry::sphere_wall));
        }
}

TEST_CASE("Willett's fit tabulated follows the closed form between its nodes, ruptures at Eq. 15", "[bridge][curve][willett]") {
    // The second route is the closed form itself, evaluated where the table interpolates.
    for (double vhat : {1e-4, 0.05544})
        for (double theta : {0.0, 30.0}) {
            INFO("V^ = " << vhat << ", theta = " << theta);
            const auto& source = *find_curve_source("willett", BridgeGeometry::sphere_sphere);
            const auto curve = source.build(vhat, deg(theta), BridgeGeometry::sphere_sphere, {});
            CHECK(curve.tabulated());
            CHECK(curve.force_scale() == Approx(2 * M_PI).epsilon(1e-15));  // Willett's F* = F/(2πRγ)
            const double hc = willett_rupture_hhat(vhat, deg(theta));
            CHECK(curve.hhat_rupture() == hc);
            // Eq. 15 by hand: (1 + θ/2)(V̂^(1/3) + 0.1 V̂^(2/3)).
            CHECK(hc == Approx((1 + deg(theta).radians() / 2) * (std::cbrt(vhat) + 0.1 * std::cbrt(vhat * vhat))).epsilon(1e-12));
            double worst = 0;
            const int n = BridgeCurve::default_gap_points;
            for (int i = 0; i + 1 < n; i += 2) {
                const double x = BridgeTable::gap_fraction((i + 0.5) / (n - 1));
                worst = std::max(worst, std::abs(curve.fhat(x * hc) / willett_full_fhat(vhat, deg(theta), x * hc) - 1));
            }
            CHECK(worst < 1e-4);
            CHECK(curve.fhat(0.0) == Approx(willett_full_fhat(vhat, deg(theta), 0.0)).epsilon(1e-12));
            CHECK(curve.fhat(hc * (1 + 1e-9)) == 0.0);
        }
}

TEST_CASE("Every bridge curve source declares what a scene's choice needs, and builds a bridge in its range", "[bridge][curve]") {
    std::set<std::pair<std::string_view, int>> values;
    for (const auto& source : curve_sources()) {
        INFO(source.value);
        CHECK_FALSE(source.value.empty());
        CHECK_FALSE(source.label.empty());
        CHECK_FALSE(source.vhat_range_name.empty());
        REQUIRE(source.build != nullptr);
        CHECK((source.sphere_sphere || source.sphere_wall));
        CHECK(0 < source.vhat_min);
        CHECK(source.vhat_min < source.vhat_max);
        // Only a fit goes without its cache line (its printed form has one of its own).
        CHECK(source.cache_name.empty() == (source.source == CurveSource::fit));
        for (auto g : {BridgeGeometry::sphere_sphere, BridgeGeometry::sphere_wall}) {
            if (!source.has(g)) continue;
            CHECK(values.insert({source.value, static_cast<int>(g)}).second);  // one value, one source
            CHECK(find_curve_source(source.value, g) == &source);
            CHECK(curve_source_values(g).find(source.value) != std::string::npos);
            // The entry a scene's settings lead back to is this one.
            CHECK(&curve_source(source.source, source.fit_variant, g) == &source);
            const double vhat = std::clamp(0.01, source.vhat_min, source.vhat_max);
            const auto curve = source.build(vhat, deg(20), g, {source.fit_variant, RuptureLaw::mikami1998});
            CHECK(std::isfinite(curve.fhat(0.0)));
            CHECK(curve.fhat(0.0) > 0);
            CHECK(curve.hhat_rupture() > 0);
            CHECK(curve.fhat(0.5 * curve.hhat_rupture()) < curve.fhat(0.0));  // it weakens as the gap opens
        }
    }
    CHECK(find_curve_source("willett", BridgeGeometry::sphere_wall) == nullptr);  // no sphere-plane form
    CHECK(find_curve_source("exact", BridgeGeometry::sphere_sphere) == nullptr);
}
