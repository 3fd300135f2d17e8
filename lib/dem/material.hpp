// Contact parameters of one material (all pairs share it in the scenes demscale builds) and the
// effective moduli of Hertz–Mindlin theory. SI units.
#pragma once

namespace demscale::dem {

struct Material {
    double density = 2500;         // kg/m³
    double youngs_modulus = 5e6;   // Pa
    double poisson_ratio = 0.3;
    double restitution = 0.5;      // normal coefficient of restitution e ∈ (0, 1]
    double friction = 0.5;         // Coulomb sliding friction μ
    double rolling_friction = 0.1; // μ_r
    double rolling_damping = 0;    // η_r, the rolling dashpot's fraction of critical damping (Ai et al. 2011; 0: none)
    double linear_stiffness = 400; // N/m, of the linear spring law: about what LIGGGHTS' hooke takes for 1 mm spheres of the default material at 0.3 m/s
    double tangential_stiffness_ratio = 2.0 / 7.0;  // κ = k_t / k_n of the linear tangential spring
};

// E* = E / (2(1 − ν²)) for two spheres of one material; G* = E / (4(2 − ν)(1 + ν)).
inline double effective_youngs(const Material& m) { return m.youngs_modulus / (2.0 * (1.0 - m.poisson_ratio * m.poisson_ratio)); }
inline double effective_shear(const Material& m) {
    return m.youngs_modulus / (4.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio));
}
// Particle–wall: the wall as the same material, same formulas with R* = R, m* = m.

// Damping ratio from restitution for the linear and Hertzian spring–dashpot:
// β = ln e / √(ln² e + π²) (Tsuji et al. 1992; as in EDEM and LIGGGHTS' hertz model). e = 1 → 0.
double damping_ratio(double restitution);

}  // namespace demscale::dem
