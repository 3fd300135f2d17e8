#include "bridge/liquid_volume.hpp"

#include "core/input_error.hpp"

namespace demscale::bridge {

double liquid_bridge_volume(double moisture_content, double particle_mass_kg, double liquid_density_kg_m3) {
    require_in_open_interval(moisture_content, 0.0, 1.0, "moisture_content");
    require_positive(particle_mass_kg, "particle_mass_kg");
    require_positive(liquid_density_kg_m3, "liquid_density_kg_per_m3");
    return moisture_content * particle_mass_kg / liquid_density_kg_m3 * eq5_bridge_fraction;  // Eq. 5
}

}  // namespace demscale::bridge
