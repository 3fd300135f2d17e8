#include "dem/law_parts.hpp"

namespace demscale::dem {

std::vector<TimeScale> time_step_limits(const ContactSettings& s, double radius_m, std::span<const LawPart> parts) {
    std::vector<TimeScale> limits;
    for (const auto& part : parts)
        if (part.time_scale && part.active(s)) limits.push_back(part.time_scale(s, radius_m));
    return limits;
}

}  // namespace demscale::dem
