// Every contact-law part a scene can use, in the order tables and decks list them. Adding a part:
// its header declares its parameters and LawPart (dem/law_part.hpp), and one line here registers
// it (docs/adding-a-contact-law.md). A law that is not a parameter group (a scene chooses it) is
// also a type the engines compile: its Registered<Law, part> line is its registration.
#pragma once

#include <array>
#include <span>
#include <tuple>
#include <type_traits>
#include <vector>

#include "dem/law_part.hpp"
#include "dem/laws/adhesion_sjkr.hpp"
#include "dem/laws/cohesion.hpp"
#include "dem/laws/normal_hertz.hpp"
#include "dem/laws/normal_linear.hpp"
#include "dem/laws/rolling.hpp"
#include "dem/laws/tangential.hpp"

namespace demscale::dem {

// A law the engines compile, with the part that declares it (its choice, deck words, report row).
template <class Law, const LawPart& Part>
struct Registered {
    using law = Law;
    static constexpr const LawPart* part = &Part;
};

// The normal laws a scene can choose (contact.normal_law), one line each.
using normal_laws = std::tuple<
    Registered<NormalHertz, hertz_part>,
    Registered<NormalLinear, hooke_part>
>;

// The law of a registered part, in a list of Registered<...>.
template <const LawPart* Part, class List>
struct law_of;
template <const LawPart* Part, class First, class... Rest>
struct law_of<Part, std::tuple<First, Rest...>> {
    // By choice value: GCC does not fold the comparison of two objects' addresses under AddressSanitizer.
    using type = std::conditional_t<First::part->choice == Part->choice, typename First::law, typename law_of<Part, std::tuple<Rest...>>::type>;
};
template <const LawPart* Part>
struct law_of<Part, std::tuple<>> {
    using type = void;  // not registered
};

// Every part, in the order tables and decks list them: the material, the normal laws, then the rest.
template <class... Normal>
constexpr auto all_law_parts(std::tuple<Normal...>*) {
    return std::array<LawPart, 7 + sizeof...(Normal)>{
        elastic_part, *Normal::part..., mindlin_part, rolling_part, rolling_dashpot_part, bridge_part, bridge_viscous_part, sjkr_part,
    };
}
inline constexpr auto registered_law_parts = all_law_parts(static_cast<normal_laws*>(nullptr));

inline std::span<const LawPart> law_parts() { return registered_law_parts; }

// A slot's default law: its first registered part with a choice (Hertz, Mindlin, ...).
inline const LawPart& default_part(Slot slot, std::span<const LawPart> parts = law_parts()) {
    for (const auto& part : parts)
        if (part.slot == slot && !part.choice.empty()) return part;
    return parts.front();  // unreachable for a slot with a registered law
}

// The choice values of the chosen laws that act in these settings, in the list's order
// ("hertz", "mindlin", "liquid_bridge"): the JSON's contact_laws, the bench's rows.
std::vector<std::string_view> chosen_laws(const ContactSettings& s, std::span<const LawPart> parts = law_parts());

// The time scales that limit a stable step of these settings, for particles of this radius (m).
std::vector<TimeScale> time_step_limits(const ContactSettings& s, double radius_m, std::span<const LawPart> parts = law_parts());

}  // namespace demscale::dem
