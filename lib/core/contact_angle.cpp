#include "core/contact_angle.hpp"

#include <cmath>

#include "core/input_error.hpp"

namespace demscale {

ContactAngle::ContactAngle(Radians r) : rad_(r.value) {
    if (!(std::isfinite(rad_) && rad_ >= 0.0 && rad_ < std::numbers::pi / 2)) {
        const bool looks_like_degrees = std::isfinite(rad_) && rad_ >= std::numbers::pi / 2 && rad_ < 90.0;
        throw InputError("contact_angle_rad", format_number(rad_),
                         std::string("[0, 1.5708) rad") +
                             (looks_like_degrees ? " (this looks like degrees: use Degrees{})" : ""));
    }
}

ContactAngle::ContactAngle(Degrees d) : rad_(0.0) {
    if (!(std::isfinite(d.value) && d.value >= 0.0 && d.value < 90.0))
        throw InputError("contact_angle_deg", format_number(d.value), "[0, 90) degrees");
    rad_ = d.value * std::numbers::pi / 180.0;
}

}  // namespace demscale
