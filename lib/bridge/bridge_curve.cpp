#include "bridge/bridge_curve.hpp"

#include <gsl/gsl_integration.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bridge/young_laplace.hpp"
#include "core/input_error.hpp"

namespace demscale::bridge {

namespace {

// Gauss–Legendre nodes and weights on [0, 1] (GSL's fixed-order table), for integrating the
// smooth tabulated F̂ segment by segment in the gap coordinate.
struct GaussLegendre {
    static constexpr int order = 10;
    std::array<double, order> x{}, w{};
    GaussLegendre() {
        gsl_integration_glfixed_table* t = gsl_integration_glfixed_table_alloc(order);
        for (int i = 0; i < order; ++i) gsl_integration_glfixed_point(0.0, 1.0, static_cast<std::size_t>(i), &x[i], &w[i], t);
        gsl_integration_glfixed_table_free(t);
    }
};
const GaussLegendre& gauss_legendre() {
    static const GaussLegendre g;
    return g;
}

}  // namespace

BridgeCurve::BridgeCurve(const MikamiCoefficients& k) : hhat_rupture_(k.hhat_rupture), force_scale_(k.force_scale), fit_(k) {}

BridgeCurve BridgeCurve::exact(double vhat, ContactAngle theta, BridgeGeometry geometry, int gap_points) {
    const YoungLaplaceBridge family = geometry == BridgeGeometry::sphere_sphere ? YoungLaplaceBridge(vhat, theta)
                                                                                : YoungLaplaceBridge::sphere_plane(vhat, theta, theta);
    return from_column(BridgeTable::solve_column(family, gap_points));  // the exact solver's F̂ is F/(2πRγ)
}

BridgeCurve BridgeCurve::tabulated(const std::function<double(double)>& fhat_of_hhat, double hhat_rupture, int gap_points) {
    if (!(std::isfinite(hhat_rupture) && hhat_rupture > 0)) throw std::runtime_error("rupture gap h^_c = " + format_number(hhat_rupture));
    BridgeTable::Pair p;
    p.hhat_rupture = hhat_rupture;
    p.even_at_rupture = true;  // a closed form has a finite slope at its rupture gap
    for (int ix = 0; ix < gap_points; ++ix) {
        const double x = BridgeTable::gap_fraction(double(ix) / (gap_points - 1)), f = fhat_of_hhat(x * hhat_rupture);
        if (!(std::isfinite(f) && f > 0)) throw std::runtime_error("F^ = " + format_number(f) + " at h^/h^_c = " + format_number(x));
        p.column.push_back(std::log(f));  // interpolated in ln F̂, as the exact column
    }
    return from_column(std::move(p));
}

BridgeCurve BridgeCurve::from_column(BridgeTable::Pair column) {
    BridgeCurve c;
    c.tabulated_ = true;
    c.force_scale_ = 2 * std::numbers::pi;
    c.column_ = std::move(column);
    c.hhat_rupture_ = c.column_.hhat_rupture;
    const int gap_points = static_cast<int>(c.column_.column.size());
    c.work_from_node_.assign(gap_points, 0.0);
    for (int i = gap_points - 2; i >= 0; --i) c.work_from_node_[i] = c.work_from_node_[i + 1] + c.work_in_segment(i, double(i) / (gap_points - 1));
    return c;
}

// ∫ F̂ dĥ from gap coordinate t_from to the next node above `node`: in t the integrand
// F̂(ĥ(t))·dĥ/dt is smooth, dĥ/dt = ĥ_c·(π/2)·sin πt.
double BridgeCurve::work_in_segment(int node, double t_from) const {
    const double t_to = double(node + 1) / (static_cast<double>(column_.column.size()) - 1);
    const auto& g = gauss_legendre();
    double sum = 0;
    for (int i = 0; i < GaussLegendre::order; ++i) {
        const double t = t_from + (t_to - t_from) * g.x[i];
        sum += g.w[i] * column_.fhat(BridgeTable::gap_fraction(t) * hhat_rupture_) * 0.5 * std::numbers::pi * std::sin(std::numbers::pi * t);
    }
    return sum * (t_to - t_from) * hhat_rupture_;
}

double BridgeCurve::work_to_rupture(double hhat) const {
    if (!tabulated_) return mikami_work_to_rupture(fit_, hhat);
    if (!(hhat < hhat_rupture_)) return 0.0;
    const double overlap_part = hhat < 0.0 ? fhat(0.0) * -hhat : 0.0;
    const int n = static_cast<int>(column_.column.size());
    const double s = BridgeTable::gap_coordinate(std::max(hhat, 0.0) / hhat_rupture_) * (n - 1);
    const int node = std::clamp(static_cast<int>(std::floor(s)), 0, n - 2);
    return overlap_part + work_in_segment(node, s / (n - 1)) + work_from_node_[node + 1];
}

}  // namespace demscale::bridge
