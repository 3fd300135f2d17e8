#include "dem/law_parts.hpp"

namespace demscale::dem {

std::vector<std::string_view> chosen_laws(const ContactSettings& s, std::span<const LawPart> parts) {
    std::vector<std::string_view> chosen;
    for (const auto& part : parts)
        if (!part.choice.empty() && part.active(s)) chosen.push_back(part.choice);
    return chosen;
}

std::vector<TimeScale> time_step_limits(const ContactSettings& s, double radius_m, std::span<const LawPart> parts) {
    std::vector<TimeScale> limits;
    for (const auto& part : parts)
        if (part.time_scale && part.active(s)) limits.push_back(part.time_scale(s, radius_m));
    return limits;
}

}  // namespace demscale::dem
