// The curves of Yun & Park (2017) Figs. 3 and 4: dimensionless capillary force F̂ and bridge stress
// σ̄ = F̄/(πR̄²) against the dimensionless gap ĥ = h/R for every Table 1 radius (and, for Fig. 4,
// every surface-tension exponent k in γ̄ = γ·S_f^k). Both Mikami variants are computed, so the
// printed-vs-published difference is visible in every curve file.
#pragma once

#include <vector>

#include "bridge/mikami_variant.hpp"
#include "io/table_config.hpp"
#include "io/table_format.hpp"

namespace demscale::report {

enum class Figure { force = 3, stress = 4 };

struct CurvePoint {
    bridge::MikamiVariant variant;
    double radius_m, sf, exponent, hhat;
    double f_over_pi_r_gamma, f_over_2pi_r_gamma;  // F̂ under both normalisations
    double force_n, sigma_pa;                       // with γ̄ = γ·S_f^k (Fig. 3: k = 0, physical γ)
    bool bridge_exists, clamped;
};

// The configured variant first, then the other one. Fig. 3 uses k = 0 (F̂ does not depend on γ).
std::vector<CurvePoint> compute_curves(const io::TableConfig& c, Figure figure, const std::vector<double>& exponents);

io::Table curves_table(const io::TableConfig& c, Figure figure, const std::vector<CurvePoint>& points);

// How well the curves of different radii collapse onto one: the largest relative spread
// (max − min)/max over radii at the same ĥ, of F̂ (Fig. 3) or σ̄ (Fig. 4). 0 = perfect collapse.
struct Collapse {
    bridge::MikamiVariant variant;
    double exponent;
    double max_relative_spread;
};
std::vector<Collapse> measure_collapse(const std::vector<CurvePoint>& points, Figure figure);

}  // namespace demscale::report
