#include "slump/coarse_grain.hpp"

#include <cmath>

#include "core/input_error.hpp"

namespace demscale::slump {

SlumpScene coarse_grained(const SlumpScene& fine, double sf, double exponent) {
    require_positive(sf, "--sf");
    require_in_open_interval(exponent, -20, 20, "--exponent");
    SlumpScene s = fine;
    s.radius_m = fine.radius_m * sf;                                                      // Eq. 9: R̄ = S_f R
    s.liquid.surface_tension_n_per_m = fine.liquid.surface_tension_n_per_m * std::pow(sf, exponent);  // Eq. 12, any k
    s.skin_m = fine.skin_m * sf;
    if (!(2 * s.radius_m < 0.5 * s.top_diameter_m))
        throw InputError("--sf", format_number(sf),
                         "< " + format_number(0.25 * s.top_diameter_m / (2 * fine.radius_m)) +
                             " (coarse particles must stay below a quarter of the cone's top opening)");
    return s;
}

}  // namespace demscale::slump
