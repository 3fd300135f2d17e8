// Liquid volume of one bridge from the moisture content, Yun & Park (2017) Eq. 5:
//   V = φ · (m / ρ_liq) · (1 − √(3/4)),
// φ = liquid mass / solid mass (fraction, not percent), m = particle mass (kg),
// ρ_liq in kg/m³, V in m³. The factor 1 − √(3/4) = 1 − cos 30° is printed without derivation.
#pragma once

namespace demscale::bridge {

inline constexpr double eq5_bridge_fraction = 0.1339745962155614;  // 1 − √(3/4)

// Throws InputError for φ outside (0, 1), m ≤ 0 or ρ_liq ≤ 0.
double liquid_bridge_volume(double moisture_content, double particle_mass_kg, double liquid_density_kg_m3);

}  // namespace demscale::bridge
