#include "slump/coarse_grain.hpp"

#include <algorithm>
#include <cmath>

#include "core/input_error.hpp"
#include "dem/time_step.hpp"
#include "similarity/exponent_similarity.hpp"

namespace demscale::slump {

SlumpScene coarse_grained(const SlumpScene& fine, const CoarseGraining& c) {
    require_positive(c.sf, "--sf");
    require_in_open_interval(c.exponent, -20, 20, "--exponent");
    SlumpScene s = fine;
    s.radius_m = fine.radius_m * c.sf;                                                          // Eq. 9: R̄ = S_f R
    s.liquid.surface_tension_n_per_m = fine.liquid.surface_tension_n_per_m * std::pow(c.sf, c.exponent);  // Eq. 12, any k
    s.skin_m = fine.skin_m * c.sf;
    for (const auto& key : c.scaled) {
        const auto& known = similarity::scalable_parameters();
        if (std::find(known.begin(), known.end(), key) == known.end())
            throw InputError("--scale", key, "gravity, youngs_modulus, velocity (the lift speed) or viscosity");
        const double factor = std::pow(c.sf, similarity::demanded_exponent(key, c.exponent, "--scale"));
        if (key == "gravity") s.gravity *= factor;
        if (key == "youngs_modulus") s.material.youngs_modulus *= factor;
        if (key == "velocity") s.lift_speed_m_per_s *= factor;
        if (key == "viscosity") s.viscosity_pa_s *= factor;
    }
    s.dt_s = fine.dt_s * dem::rayleigh_time(s.material, s.radius_m) / dem::rayleigh_time(fine.material, fine.radius_m);
    if (!(2 * s.radius_m < s.top_diameter_m))
        throw InputError("--sf", format_number(c.sf),
                         "< " + format_number(0.5 * s.top_diameter_m / fine.radius_m) +
                             " (a coarse particle must pass the cone's top opening)");
    return s;
}

std::vector<std::string> geometry_warnings(const SlumpScene& s, std::size_t particles) {
    std::vector<std::string> w;
    const double d = 2 * s.radius_m;
    if (s.top_diameter_m < 5 * d)
        w.push_back("top opening " + format_short(s.top_diameter_m / d, 2) + " diameters wide (< 5)");
    if (s.fill_height_m < 10 * d) w.push_back("fill " + format_short(s.fill_height_m / d, 2) + " diameters high (< 10)");
    if (particles < 200) w.push_back(std::to_string(particles) + " particles (< 200)");
    return w;
}

}  // namespace demscale::slump
