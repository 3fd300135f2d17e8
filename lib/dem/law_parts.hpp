// Every contact-law part a scene can use, in the order tables and decks list them. Adding a part:
// its header declares its parameters and LawPart (dem/law_part.hpp), and one line here registers
// it (docs/adding-a-contact-law.md).
#pragma once

#include <span>
#include <vector>

#include "dem/law_part.hpp"
#include "dem/laws/adhesion_sjkr.hpp"
#include "dem/laws/cohesion.hpp"
#include "dem/laws/normal_hertz.hpp"
#include "dem/laws/rolling.hpp"
#include "dem/laws/tangential.hpp"

namespace demscale::dem {

inline constexpr LawPart registered_law_parts[] = {
    hertz_part,
    mindlin_part,
    rolling_part,
    rolling_dashpot_part,
    bridge_part,
    bridge_viscous_part,
    sjkr_part,
};

inline std::span<const LawPart> law_parts() { return registered_law_parts; }

// The time scales that limit a stable step of these settings, for particles of this radius (m).
std::vector<TimeScale> time_step_limits(const ContactSettings& s, double radius_m, std::span<const LawPart> parts = law_parts());

}  // namespace demscale::dem
