// Particle replacement (Yun & Park 2017 Eqs. 9–10): one coarse particle of radius R̄ = S_f·R replaces
// S_f³ physical ones of the same material, V̄ = V·S_f³, m̄ = m·S_f³. Its liquid per bridge follows
// Eq. 5 with the coarse mass, so V̂ = V_liq/R̄³ is the same at every S_f. SI units.
#pragma once

#include "core/contact_angle.hpp"

namespace demscale::similarity {

struct Liquid {
    double surface_tension_n_per_m = 0.074;
    ContactAngle contact_angle{Degrees{0.0}};
    double density_kg_per_m3 = 1000.0;
    double moisture_content = 0.045;  // liquid mass / solid mass (Eq. 5's φ)
};

struct ParticleDescription {
    double sf = 1;                 // S_f = R̄ / R_physical
    double radius_m = 0;
    double volume_m3 = 0;          // 4/3 π R³
    double mass_kg = 0;
    double replaced_count = 1;     // physical particles one particle stands for: S_f³
    double liquid_volume_m3 = 0;   // per bridge, Eq. 5
    double vhat = 0;               // V_liq / R³, Eq. 4
};

// A particle of given radius and mass (the mass may come from a table rather than a density).
ParticleDescription describe_particle(double sf, double radius_m, double mass_kg, const Liquid& liquid);

// Eqs. 9–10: the coarse particle replacing S_f³ physical particles of radius R and density ρ.
ParticleDescription replace_particle(double physical_radius_m, double solid_density_kg_per_m3, double sf,
                                     const Liquid& liquid);

}  // namespace demscale::similarity
