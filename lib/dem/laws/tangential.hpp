// Tangential contact laws.
//  TangentialNone  — frictionless: no state, no code in the force loop.
//  TangentialMindlin — incremental spring with history (Mindlin & Deresiewicz 1953 no-slip stiffness
//    S_t = 8 G* √(R* δ)), damping −2√(5/6) β √(S_t m*) v_t, Coulomb limit |F_t| ≤ μ F_n; on sliding
//    the spring is reset to the limit (as in LIGGGHTS' tangential_history). SI units.
//  TangentialLinear — the same with a constant stiffness k_t = κ k_n and the linear dashpot.
//    Ledger: the dashpot loses c|v_t|²dt; a sliding step loses the work −F_t·Δξ less the spring's
//    energy change (the energy the Coulomb cap removes); the stiffness change is booked apart.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/law_part.hpp"
#include "dem/energy.hpp"
#include "dem/laws/plastic_limit.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct TangentialNone {
    struct State {};
    template <class Lost>
    using StateFor = State;
    explicit TangentialNone(const Material&) {}
    double stiffness(const ContactPair&) const { return 0.0; }
    template <class Lost>
    Vec3 force(const ContactPair&, double, State&, Lost&) const { return Vec3::Zero(); }
    double stored_energy(const ContactPair&, const State&) const { return 0.0; }
    template <class Lost>
    void release(State&, Lost&) const {}
};

// Tangential spring with history and a Coulomb limit; the spring law (stiffness and dashpot) is the
// parameter. A fresh contact starts at zero; on sliding the spring is reset to the limit.
template <class Spring>
struct TangentialHistory {
    template <class Lost>  // Dissipation: with the ledger's S_t of the last step; NoDissipation: without
    struct StateFor {
        Vec3 spring = Vec3::Zero();                          // accumulated tangential displacement ξ, m
        [[no_unique_address]] LastStiffness<Lost> stiffness; // S_t at the last step, N/m
    };
    using State = StateFor<Dissipation>;
    Spring law;
    double mu;

    explicit TangentialHistory(const Material& m) : law(m), mu(m.friction) {}

    double stiffness(const ContactPair& c) const { return law.stiffness(c); }

    // normal_force: the total normal force (for the Coulomb limit); lost: what this step dissipates is added.
    // Lost: Dissipation, or NoDissipation to book nothing.
    template <class Lost>
    DEMSCALE_HOT Vec3 force(const ContactPair& c, double normal_force, StateFor<Lost>& s, Lost& lost) const {
        // Keep the spring in the current tangent plane, at its length (the pair may have rotated).
        const double length2 = s.spring.squaredNorm();
        if (length2 > 0) {  // a fresh contact has none to turn
            s.spring -= c.normal * c.normal.dot(s.spring);
            const double projected2 = s.spring.squaredNorm();
            if (projected2 > 0) s.spring *= std::sqrt(length2 / projected2);  // one root, not two
        }
        const double st = stiffness(c);
        const double stored_before = 0.5 * st * length2;  // the rotation kept the length
        if constexpr (books_losses<Lost>) {
            lost.spring_stiffness += 0.5 * (s.stiffness.value - st) * length2;
            s.stiffness.value = st;
        }
        s.spring += c.v_tangential * c.dt;
        const double damping = law.damping(c, st);  // ≥ 0 (β ≤ 0): opposes v_t
        Vec3 f = -st * s.spring - damping * c.v_tangential;
        const double limit = mu * std::abs(normal_force);
        if (const double magnitude = beyond_limit(f.squaredNorm(), limit)) {  // sliding: cap at μF_n, spring consistent
            f *= limit / magnitude;
            s.spring = st > 0 ? Vec3(-f / st) : Vec3::Zero();
            lost.friction += -f.dot(c.v_tangential) * c.dt - (0.5 * st * s.spring.squaredNorm() - stored_before);
        } else {
            lost.friction += damping * c.v_tangential.squaredNorm() * c.dt;
        }
        return f;
    }

    // The surfaces parted: the spring lets go of what it held.
    template <class Lost>
    void release(StateFor<Lost>& s, Lost& lost) const {
        if constexpr (books_losses<Lost>) {
            if (s.stiffness.value == 0) return;  // nothing held (the common case: a listed pair apart)
            lost.spring_stiffness += 0.5 * s.stiffness.value * s.spring.squaredNorm();
        }
        s = {};
    }

    // ½ S_t |ξ|², J.
    template <class Lost>
    double stored_energy(const ContactPair& c, const StateFor<Lost>& s) const {
        return c.overlap > 0 ? 0.5 * stiffness(c) * s.spring.squaredNorm() : 0.0;
    }
};

// Mindlin & Deresiewicz (1953) no-slip stiffness S_t = 8 G* √(R* δ), dashpot −2√(5/6) β √(S_t m*)
// (the Hertzian form, as LIGGGHTS' hertz tangential history).
struct MindlinSpring {
    double g_star, beta;
    double dashpot;  // 2 √(5/6) β √(8G*), Pa^½
    explicit MindlinSpring(const Material& m)
        : g_star(effective_shear(m)), beta(damping_ratio(m.restitution)), dashpot(2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(8.0 * g_star)) {}
    double stiffness(const ContactPair& c) const { return 8.0 * g_star * c.contact_radius; }
    // −2 √(5/6) β √(S_t m*) = −dashpot √a √m*: the same √a as the normal dashpot's (S_t is st).
    double damping(const ContactPair& c, double) const { return -dashpot * std::sqrt(c.contact_radius) * c.sqrt_m_eff; }
};

// Linear spring k_t = κ k_n (Material::tangential_stiffness_ratio, 2/7 by default: then a sticking
// sphere's tangential and normal oscillations take equal times), dashpot −2β √(k_t m*), the
// normal law's damping ratio (as the linear normal dashpot). For use with NormalLinear.
struct LinearTangentialSpring {
    double k_t, beta;
    explicit LinearTangentialSpring(const Material& m)
        : k_t(m.tangential_stiffness_ratio * m.linear_stiffness), beta(damping_ratio(m.restitution)) {}
    double stiffness(const ContactPair&) const { return k_t; }
    double damping(const ContactPair& c, double st) const { return -2.0 * beta * std::sqrt(st * c.m_eff); }
};

using TangentialMindlin = TangentialHistory<MindlinSpring>;
using TangentialLinear = TangentialHistory<LinearTangentialSpring>;

// Parameters (docs/models/tangential-mindlin.md); the stiffness follows the normal law's E and ν.
inline constexpr Parameter mindlin_parameters[] = {
    {"contact.friction", "sliding friction", "1", {}, 0.5, {0, 10}, Replacement::kept, {}, "coefficientFriction",
     LiggghtsKind::per_type_pair, [](const ContactSettings& s) { return s.material.friction; },
     [](ContactSettings& s, double x) { s.material.friction = x; }},
};
inline constexpr LawPart mindlin_part{.name = "Mindlin tangential contact with Coulomb friction",
                                      .parameters = mindlin_parameters,
                                      .active = [](const ContactSettings&) { return true; },
                                      .liggghts_model = "tangential history",
                                      .slot = Slot::tangential,
                                      .choice = "mindlin",
                                      .choose = [](ContactSettings&) {}};

}  // namespace demscale::dem
