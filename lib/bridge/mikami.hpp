// Static pendular liquid bridge: Mikami, Kamiya & Horio (1998) regression of Young–Laplace
// solutions, as printed in Yun & Park (2017) Eqs. 1–8 (sphere–sphere) and Mikami's
// sphere–wall fit (docs/model.md §1). Units: SI; ĥ = full surface gap / R, V̂ = V / R³, θ in radians.
//
// Policy at the edges (docs/model.md §7):
//  * ĥ < 0 (overlap) uses the contact value ĥ = 0.
//  * ĥ > ĥ_rupture: no bridge, force exactly 0.
//  * Where the fit turns negative before rupture (C < 0 and exp(Aĥ+B) < −C: the printed
//    variant at V̂ ≲ 0.16, Mikami's at V̂ < 8.6e-9) F̂ is clamped to 0 and the evaluation says so.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

#include "bridge/mikami_variant.hpp"
#include "core/contact_angle.hpp"

namespace demscale::bridge {

struct MikamiOptions {
    MikamiVariant variant = MikamiVariant::mikami1998;
    RuptureLaw rupture = RuptureLaw::mikami1998;  // sphere–wall always uses Mikami's wall law
};

// Everything one pair type needs; computed once so that a force costs one exp.
struct MikamiCoefficients {
    double a = 0;             // Eq. 6 (wall: D)
    double b = 0;             // Eq. 7 (wall: E)
    double c = 0;             // Eq. 8 (wall: F)
    double hhat_rupture = 0;  // rupture gap / R
    double force_scale = 0;   // F = force_scale·R·γ·F̂: π (mikami1998) or 2π (Eq. 1 as printed)
    MikamiVariant variant = MikamiVariant::mikami1998;
    BridgeGeometry geometry = BridgeGeometry::sphere_sphere;
};

// Throws InputError for V̂ not finite and > 0.
MikamiCoefficients mikami_coefficients(double vhat, ContactAngle theta, const MikamiOptions& options = {},
                                       BridgeGeometry geometry = BridgeGeometry::sphere_sphere);

// Hot path (DEM inner loop): F̂ = exp(A·max(ĥ,0) + B) + C, Eq. 2; 0 beyond rupture; ≥ 0.
inline double mikami_fhat(const MikamiCoefficients& k, double hhat) {
    if (!(hhat <= k.hhat_rupture)) return 0.0;
    const double raw = std::exp(k.a * (hhat > 0.0 ? hhat : 0.0) + k.b) + k.c;
    return raw > 0.0 ? raw : 0.0;
}

// Checked evaluation for tools and tables: also says whether a bridge exists and whether
// the fit had to be clamped. Throws InputError for non-finite ĥ.
struct MikamiEvaluation {
    double fhat = 0;          // F / (force_scale·R·γ)
    double raw = 0;           // exp(Aĥ+B)+C before clamping (0 beyond rupture)
    bool bridge_exists = false;
    bool clamped = false;     // the regression was negative here and was clamped to 0
};
MikamiEvaluation evaluate_mikami(const MikamiCoefficients& k, double hhat);

// ĥ at which the regression crosses zero before rupture, if it does (where clamping starts).
std::optional<double> negative_onset_hhat(const MikamiCoefficients& k);

// ∫ F̂ dĥ' from ĥ to rupture (Eq. 2 integrated in closed form): the work, in units of
// force_scale·R²·γ, to pull a bridge from gap ĥ until it ruptures; an overlap (ĥ < 0) adds F̂(0)·|ĥ|.
// The bridge's potential energy in the DEM ledger is minus this. 0 for ĥ ≥ ĥ_rupture.
double mikami_work_to_rupture(const MikamiCoefficients& k, double hhat);

// Capillary force in newtons, F = force_scale·R·γ·F̂ (Eq. 1). R in m, γ in N/m.
// Throws std::overflow_error if the product is not finite.
double bridge_force_newton(const MikamiCoefficients& k, double fhat, double radius_m, double gamma_n_per_m);

// The same force under both normalisations people print: F/(πRγ) and F/(2πRγ).
inline double f_over_pi_r_gamma(const MikamiCoefficients& k, double fhat) {
    return fhat * k.force_scale / std::numbers::pi;
}
inline double f_over_2pi_r_gamma(const MikamiCoefficients& k, double fhat) {
    return fhat * k.force_scale / (2.0 * std::numbers::pi);
}

// Rupture distance ĥ_c for equal spheres under the chosen law (θ in radians).
double rupture_hhat(double vhat, ContactAngle theta, RuptureLaw law);

}  // namespace demscale::bridge
