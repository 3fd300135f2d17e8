#include "similarity/particle_replacement.hpp"

#include <cmath>
#include <numbers>

#include "bridge/liquid_volume.hpp"
#include "core/input_error.hpp"

namespace demscale::similarity {

ParticleDescription describe_particle(double sf, double radius_m, double mass_kg, const Liquid& liquid) {
    require_positive(sf, "sf");
    require_positive(radius_m, "radius_m");
    require_positive(mass_kg, "mass_kg");
    ParticleDescription p;
    p.sf = sf;
    p.radius_m = radius_m;
    p.volume_m3 = 4.0 / 3.0 * std::numbers::pi * radius_m * radius_m * radius_m;
    p.mass_kg = mass_kg;
    p.replaced_count = sf * sf * sf;
    p.liquid_volume_m3 = bridge::liquid_bridge_volume(liquid.moisture_content, mass_kg, liquid.density_kg_per_m3);
    p.vhat = p.liquid_volume_m3 / (radius_m * radius_m * radius_m);  // Eq. 4
    if (!std::isfinite(p.volume_m3) || !std::isfinite(p.vhat) || p.vhat <= 0.0)
        throw InputError("radius_m", format_number(radius_m), "a radius whose volume is a finite number > 0");
    return p;
}

ParticleDescription replace_particle(double physical_radius_m, double solid_density_kg_per_m3, double sf,
                                     const Liquid& liquid) {
    require_positive(physical_radius_m, "physical_radius_m");
    require_positive(solid_density_kg_per_m3, "solid_density_kg_per_m3");
    require_positive(sf, "sf");
    const double r = sf * physical_radius_m;                                          // R̄ = S_f R
    const double m = solid_density_kg_per_m3 * 4.0 / 3.0 * std::numbers::pi * r * r * r;  // Eq. 10: ρ V̄
    return describe_particle(sf, r, m, liquid);
}

}  // namespace demscale::similarity
