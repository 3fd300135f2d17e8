// What a contact-law part declares about itself, once, in its own header: its parameters (scene
// key, unit, dimension, default, accepted range, rule under particle replacement, LIGGGHTS name),
// when it acts, and the time scale that limits a stable step. These declarations drive the scene
// reader, the run-cache key, the report's input table, the LIGGGHTS export, the coarse-graining
// of a scene and its time-step check (dem/law_parts.hpp lists them; docs/adding-a-contact-law.md).
#pragma once

#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "core/input_error.hpp"
#include "dem/contact_settings.hpp"
#include "similarity/dimension.hpp"

namespace demscale::dem {

inline constexpr double unbounded = std::numeric_limits<double>::infinity();

// The accepted values, in the unit at the input edge (never NaN or infinity).
struct Range {
    double lo, hi;
    bool lo_open = true, hi_open = true;
    bool contains(double x) const { return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi); }
    std::string text() const {  // "(0, 1]", or "a finite number > 0" when unbounded above
        if (hi == unbounded) return std::string(lo_open ? "a finite number > " : "a finite number >= ") + format_number(lo);
        return (lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) + (hi_open ? ")" : "]");
    }
};

// How a parameter changes when one particle of radius S_f·R replaces S_f³ (Yun & Park 2017,
// Eqs. 9-12): kept (dimensionless, or held at its physical value); the surface tension's
// γ̄ = γ·S_f^k (Eq. 12, the candidate exponent); or kept unless named in --scale, then scaled by
// S_f^e with e what its dimension demands under the basis k implies (docs/model.md).
enum class Replacement { kept, surface_tension, scalable };

// How the LIGGGHTS deck states it: fix property/global NAME peratomtype V, peratomtypepair 1 V,
// or scalar V. An empty name: not exported.
enum class LiggghtsKind { per_type, per_type_pair, scalar };

struct Parameter {
    std::string_view key;    // scene key, section.name: "contact.youngs_modulus_pa"
    std::string_view label;  // for people: "Young's modulus E"
    std::string_view unit;   // at the input edge (the key's suffix)
    similarity::Dimension dimension;  // of the SI value: L, ρ, T exponents
    double default_value;    // input unit
    Range accepted;          // input unit
    Replacement replacement = Replacement::kept;
    std::string_view scale_name = {};  // --scale NAME, for Replacement::scalable
    std::string_view liggghts = {};
    LiggghtsKind liggghts_kind = LiggghtsKind::per_type_pair;
    // The value in the input unit, read from and written into the settings (SI inside).
    double (*get)(const ContactSettings&) = nullptr;
    void (*set)(ContactSettings&, double) = nullptr;
};

// A stable step needs dt ≤ fraction × seconds (e.g. 0.2 × the Rayleigh time).
struct TimeScale {
    double seconds = 0;
    double fraction = 0.2;
    std::string_view name;  // "the Rayleigh time"
};

// The place a part takes in the contact law (ContactLaw<Normal, Tangential, Cohesion, Rolling>).
enum class Slot { normal, tangential, rolling, cohesion };

// The scene key whose value chooses a slot's part among the registered ones ("contact.normal_law");
// empty: the slot is chosen by other keys (rolling: contact.rolling_resistance and rolling_model;
// cohesion: liquid.wet, or SJKR's energy density) or has one part.
constexpr std::string_view slot_key(Slot slot) { return slot == Slot::normal ? "contact.normal_law" : ""; }

struct LawPart {
    std::string_view name = {};              // "Hertz normal contact": also its row in the report
    std::span<const Parameter> parameters = {};
    bool (*active)(const ContactSettings&) = nullptr;  // whether a scene with these settings uses it
    // The time scale its stiffness or damping imposes on particles of radius R (m); none: nullptr.
    TimeScale (*time_scale)(const ContactSettings&, double radius_m) = nullptr;
    std::string_view liggghts_extra = {};    // a fixed "property/global ..." the LIGGGHTS deck needs when it acts
    std::string_view liggghts_model = {};    // its words in the deck's pair style ("cohesion sjkr"); empty: none
    std::string_view liggghts_setting = {};  // a keyword/value the pair style then needs ("tangential_reduce on")
    // Whether a scene may give its parameters values other than their defaults (nullptr: always);
    // the scene reader refuses one otherwise, with `allowed_text` as the accepted value.
    bool (*allowed)(const ContactSettings&) = nullptr;
    std::string_view allowed_text = {};
    // A part a scene chooses (a law of its slot; the others are parameter groups of the law before
    // them): its slot, the value that names it (the slot key's value, the engine list's and the run
    // cache's word for it), how a scene is made to choose it (the scene reader calls it for the
    // slot key's value; tests for every part), and what the LIGGGHTS deck's header says of it
    // where it has no words there or they differ. Its builder: dem/law_builder.hpp.
    Slot slot = Slot::normal;
    std::string_view choice = {};
    void (*choose)(ContactSettings&) = nullptr;
    std::string_view liggghts_note = {};
    bool liggghts_walls = true;  // its deck words apply to wall contacts too
};

}  // namespace demscale::dem
