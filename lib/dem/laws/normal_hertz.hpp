// Hertz (1882) normal contact with viscous damping from the coefficient of restitution:
//   F_el = 4/3 E* √R* δ^(3/2),  S_n = 2 E* √(R* δ),
//   F_d  = −2 √(5/6) β √(S_n m*) v_n,  β = ln e / √(ln² e + π²)
// (Tsuji, Tanaka & Ishida 1992 damping in the form used by EDEM and LIGGGHTS' hertz model). SI units.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/law_part.hpp"
#include "dem/material.hpp"
#include "dem/time_step.hpp"

namespace demscale::dem {

struct NormalHertz {
    double e_star;  // Pa
    double beta;    // damping ratio (≤ 0)
    double dashpot; // 2 √(5/6) β √(2E*), Pa^½: F_d = dashpot √a √m* v_n with a = √(R* δ)

    explicit NormalHertz(const Material& m)
        : e_star(effective_youngs(m)), beta(damping_ratio(m.restitution)), dashpot(2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(2.0 * e_star)) {}

    // Tangent normal stiffness S_n = dF_el/dδ, which scales the damping.
    double stiffness(const ContactPair& c) const { return 2.0 * e_star * c.contact_radius; }
    // 4/3 E* √R* δ^(3/2) = 4/3 E* a δ: the contact radius carries the root.
    double elastic_force(const ContactPair& c) const { return secant_stiffness(c) * c.overlap; }
    // F_el / δ = 4/3 E* a, N/m (the rolling laws' k_n, as LIGGGHTS' kn).
    double secant_stiffness(const ContactPair& c) const { return 4.0 / 3.0 * e_star * c.contact_radius; }
    // 2 √(5/6) β √(S_n m*) v_n (β ≤ 0, v_n < 0 approaching: it pushes apart) with √(S_n m*) =
    // √(2E*) √a √m*: √a is the tangential dashpot's too.
    double damping_force(const ContactPair& c) const { return dashpot * std::sqrt(c.contact_radius) * c.sqrt_m_eff * c.v_normal; }
    // Stored energy 8/15 E* √R* δ^(5/2).
    double elastic_energy(const ContactPair& c) const {
        return 8.0 / 15.0 * e_star * c.sqrt_r_eff * std::pow(c.overlap, 2.5);
    }
};

// The elastic material (docs/models/hertz-normal.md): E, ν and e act in every contact (the Mindlin
// spring reads E and ν, every normal law's damping e), whichever normal law a scene chooses. E is a
// stress: kept, or scaled by --scale youngs_modulus.
inline constexpr Parameter elastic_parameters[] = {
    {"contact.youngs_modulus_pa", "Young's modulus E", "Pa", {2, 1, -2}, 5e6, {0, unbounded}, Replacement::scalable,
     "youngs_modulus", "youngsModulus", LiggghtsKind::per_type,
     [](const ContactSettings& s) { return s.material.youngs_modulus; },
     [](ContactSettings& s, double x) { s.material.youngs_modulus = x; }},
    {"contact.poisson_ratio", "Poisson's ratio", "1", {}, 0.3, {-1, 0.5}, Replacement::kept, {}, "poissonsRatio",
     LiggghtsKind::per_type, [](const ContactSettings& s) { return s.material.poisson_ratio; },
     [](ContactSettings& s, double x) { s.material.poisson_ratio = x; }},
    {"contact.restitution", "restitution", "1", {}, 0.5, {0, 1, true, false}, Replacement::kept, {}, "coefficientRestitution",
     LiggghtsKind::per_type_pair, [](const ContactSettings& s) { return s.material.restitution; },
     [](ContactSettings& s, double x) { s.material.restitution = x; }},
};

// A stable step: dt ≤ 0.2 × the Rayleigh time of E, ν and ρ (docs/model.md, time_step.hpp), which
// the Mindlin spring imposes whatever the normal law.
inline constexpr LawPart elastic_part{
    "elastic material", elastic_parameters, [](const ContactSettings&) { return true; },
    [](const ContactSettings& s, double radius) { return TimeScale{rayleigh_time(s.material, radius), 0.2, "the Rayleigh time"}; }};

// Hertz's law, the default of contact.normal_law; LIGGGHTS' model hertz.
inline constexpr LawPart hertz_part{.name = "Hertz normal contact",
                                    .active = [](const ContactSettings& s) { return s.normal_law == "hertz"; },
                                    .liggghts_model = "model hertz",
                                    .slot = Slot::normal,
                                    .choice = "hertz",
                                    .choose = [](ContactSettings& s) { s.normal_law = "hertz"; }};

}  // namespace demscale::dem
