// One pair type's static liquid bridge along the gap, as the DEM evaluates it:
// F = force_scale·R·γ·F̂(ĥ) up to the rupture gap ĥ_c, 0 beyond (ĥ = gap/R, < 0 an overlap, which
// counts as contact). Two forms (docs/models/liquid-bridge.md):
//  * a Mikami et al. (1998) regression (Yun & Park 2017 Eqs. 1–8, or the sphere–wall fit): one exp;
//  * a column tabulated along the gap on BridgeTable's nodes and cubic (an acos and an exp per
//    call): the exact Young–Laplace bridge (sphere–sphere or sphere–plane) solved at one (V̂, θ),
//    or a closed form such as Willett et al.'s (2000) fit.
// Every DEM pair shares one V̂, so one column is exact in (V̂, θ) and only the gap is interpolated.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bridge/bridge_table.hpp"
#include "bridge/mikami.hpp"

namespace demscale::bridge {

// Where a scene's bridges take their curve from: the scene's Mikami fit, the exact bridge, or
// Willett et al.'s (2000) full fit; what each source declares: bridge/curve_sources.hpp.
enum class CurveSource { fit, exact, willett };

class BridgeCurve {
public:
    // A Mikami fit is a curve (implicit: the fit's coefficients go wherever a curve does).
    BridgeCurve(const MikamiCoefficients& k);  // NOLINT(google-explicit-constructor)
    // The exact bridge of V̂ (V/R³) at contact angle θ (on both surfaces) between equal spheres or
    // a sphere and a plate, tabulated at gap_points nodes (0.3–0.5 s per column). Throws
    // std::runtime_error where the exact solver finds no concave bridge (the message says why).
    static BridgeCurve exact(double vhat, ContactAngle theta, BridgeGeometry geometry, int gap_points = default_gap_points);
    static constexpr int default_gap_points = 65;
    // A closed form F̂ = F/(2πRγ) of ĥ up to its rupture gap, tabulated on the same nodes (its slope
    // at rupture finite: even_at_rupture). Throws std::runtime_error where F̂ is not finite and > 0.
    static BridgeCurve tabulated(const std::function<double(double)>& fhat_of_hhat, double hhat_rupture, int gap_points = default_gap_points);

    bool tabulated() const { return tabulated_; }
    double hhat_rupture() const { return hhat_rupture_; }
    double force_scale() const { return force_scale_; }  // π or 2π: F = force_scale·R·γ·F̂

    // F̂ at gap ĥ (the DEM's hot path); 0 beyond rupture, ≥ 0.
    double fhat(double hhat) const { return tabulated_ ? column_.fhat(hhat) : mikami_fhat(fit_, hhat); }

    // ∫ F̂ dĥ' from ĥ to rupture, in units of force_scale·R²·γ: the work to pull the bridge from ĥ
    // until it ruptures (an overlap adds F̂(0)·|ĥ|); the bridge's potential is minus this. 0 beyond.
    double work_to_rupture(double hhat) const;

private:
    BridgeCurve() = default;
    bool tabulated_ = false;
    double hhat_rupture_ = 0, force_scale_ = 0;
    MikamiCoefficients fit_;
    BridgeTable::Pair column_;
    std::vector<double> work_from_node_;  // work_to_rupture at each gap node (tabulated only)
    static BridgeCurve from_column(BridgeTable::Pair column);  // F/(2πRγ) on the gap nodes
    double work_in_segment(int node, double t_from) const;
};

}  // namespace demscale::bridge
