// An engine's contact law, built from a scene's settings: each part by its own builder, a static
// build(settings, sizes, where) where it declares one (the liquid bridge, SJKR, the run-time
// rolling law), else its constructor from the material. Nothing outside lib/dem/ builds a law
// (docs/adding-a-contact-law.md).
#pragma once

#include <string>

#include "dem/bridge_law.hpp"
#include "dem/contact_law.hpp"
#include "dem/contact_settings.hpp"

namespace demscale::dem {

// Particles of these sizes (m); `where` (the scene file) opens an error's field.
template <class Part>
Part build_part(const ContactSettings& s, const LawSizes& sizes, const std::string& where) {
    if constexpr (requires { Part::build(s, sizes, where); }) return Part::build(s, sizes, where);
    else if constexpr (std::is_constructible_v<Part, const Material&>) return Part(s.material);
    else return Part{};
}

template <class Law>
struct LawBuilder;
template <class Normal, class Tangential, class Cohesion, class Rolling>
struct LawBuilder<ContactLaw<Normal, Tangential, Cohesion, Rolling>> {
    static ContactLaw<Normal, Tangential, Cohesion, Rolling> build(const ContactSettings& s, const LawSizes& sizes, const std::string& where) {
        static_assert(std::is_constructible_v<Normal, const Material&> && std::is_constructible_v<Tangential, const Material&>,
                      "a normal or tangential law is built from the material");
        return {s.material, build_part<Cohesion>(s, sizes, where), build_part<Rolling>(s, sizes, where)};
    }
};

template <class Law>
Law build_contact_law(const ContactSettings& s, const LawSizes& sizes, const std::string& where = {}) {
    return LawBuilder<Law>::build(s, sizes, where);
}
// Particles of one radius (m).
template <class Law>
Law build_contact_law(const ContactSettings& s, double radius_m, const std::string& where = {}) {
    return build_contact_law<Law>(s, LawSizes{radius_m, radius_m}, where);
}

}  // namespace demscale::dem
