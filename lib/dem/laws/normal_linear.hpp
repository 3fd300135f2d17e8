// Linear spring–dashpot normal contact: F = k δ − c v_n with c = −2β √(k m*), β from the
// restitution (Tsuji et al. 1992), which gives exactly e for an isolated collision. SI units.
// A scene chooses it with contact.normal_law = "hooke" (docs/models/linear-normal.md).
#pragma once

#include <cmath>
#include <numbers>

#include "dem/contact_pair.hpp"
#include "dem/law_part.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct NormalLinear {
    double k;     // N/m
    double beta;  // ≤ 0

    explicit NormalLinear(const Material& m) : k(m.linear_stiffness), beta(damping_ratio(m.restitution)) {}

    double elastic_force(const ContactPair& c) const { return k * c.overlap; }
    double secant_stiffness(const ContactPair&) const { return k; }  // F_el / δ, N/m
    double damping_force(const ContactPair& c) const { return 2.0 * beta * std::sqrt(k * c.m_eff) * c.v_normal; }
    double elastic_energy(const ContactPair& c) const { return 0.5 * k * c.overlap * c.overlap; }
};

// k is a stiffness, N/m = ρ L³ T⁻²: kept, or scaled by --scale linear_stiffness (S_f¹ where
// stresses are kept, k = 1). LIGGGHTS has no k of its own: its hooke derives one.
inline constexpr Parameter hooke_parameters[] = {
    {"contact.linear_stiffness_n_per_m", "linear normal stiffness k_n", "N/m", {3, 1, -2}, 400, {0, unbounded}, Replacement::scalable,
     "linear_stiffness", {}, LiggghtsKind::scalar, [](const ContactSettings& s) { return s.material.linear_stiffness; },
     [](ContactSettings& s, double x) { s.material.linear_stiffness = x; }},
};

// A resolved collision: dt ≤ t_c / 20 with t_c = π √(m*/k), m* = m/2 of two equal spheres.
inline constexpr LawPart hooke_part{
    .name = "linear spring-dashpot normal contact (Hooke)",
    .parameters = hooke_parameters,
    .active = [](const ContactSettings& s) { return s.normal_law == "hooke"; },
    .time_scale = [](const ContactSettings& s, double radius) {
        const double m = s.material.density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
        return TimeScale{std::numbers::pi * std::sqrt(0.5 * m / s.material.linear_stiffness), 0.05, "the collision time pi sqrt(m*/k)"};
    },
    .liggghts_extra = "property/global characteristicVelocity scalar 0.3",
    .liggghts_model = "model hooke",
    .slot = Slot::normal,
    .choice = "hooke",
    .choose = [](ContactSettings& s) { s.normal_law = "hooke"; },
    .liggghts_note = "LIGGGHTS' model hooke derives k_n from E*, R*, m* and characteristicVelocity (0.3 m/s here), "
                     "not from contact.linear_stiffness_n_per_m: the stiffnesses differ",
};

}  // namespace demscale::dem
