// Tangential contact laws.
//  TangentialNone  — frictionless: no state, no code in the force loop.
//  TangentialMindlin — incremental spring with history (Mindlin & Deresiewicz 1953 no-slip stiffness
//    S_t = 8 G* √(R* δ)), damping −2√(5/6) β √(S_t m*) v_t, Coulomb limit |F_t| ≤ μ F_n; on sliding
//    the spring is reset to the limit (as in LIGGGHTS' tangential_history). SI units.
//    Ledger: the dashpot loses c|v_t|²dt; a sliding step loses the work −F_t·Δξ less the spring's
//    energy change (the energy the Coulomb cap removes); the stiffness change is booked apart.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/energy.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct TangentialNone {
    struct State {};
    explicit TangentialNone(const Material&) {}
    template <class Lost>
    Vec3 force(const ContactPair&, double, State&, Lost&) const { return Vec3::Zero(); }
    double stored_energy(const ContactPair&, const State&) const { return 0.0; }
    template <class Lost>
    void release(State&, Lost&) const {}
};

struct TangentialMindlin {
    struct State {
        Vec3 spring = Vec3::Zero();  // accumulated tangential displacement ξ, m
        double stiffness = 0;        // S_t at the last step, N/m (for the ledger)
    };
    double g_star, beta, mu;

    explicit TangentialMindlin(const Material& m)
        : g_star(effective_shear(m)), beta(damping_ratio(m.restitution)), mu(m.friction) {}

    double stiffness(const ContactPair& c) const { return 8.0 * g_star * c.contact_radius; }

    // normal_force: the total normal force (for the Coulomb limit); lost: what this step dissipates is added.
    // Lost: Dissipation, or NoDissipation to book nothing.
    template <class Lost>
    Vec3 force(const ContactPair& c, double normal_force, State& s, Lost& lost) const {
        // Keep the spring in the current tangent plane, at its length (the pair may have rotated).
        const double length2 = s.spring.squaredNorm();
        if (length2 > 0) {  // a fresh contact has none to turn
            const double length = std::sqrt(length2);
            s.spring -= c.normal * c.normal.dot(s.spring);
            const double projected = s.spring.norm();
            if (projected > 0) s.spring *= length / projected;
        }
        const double st = stiffness(c);
        const double stored_before = 0.5 * st * length2;  // the rotation kept the length
        lost.spring_stiffness += 0.5 * (s.stiffness - st) * length2;
        s.stiffness = st;
        s.spring += c.v_tangential * c.dt;
        const double damping = -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(st * c.m_eff);
        Vec3 f = -st * s.spring - damping * c.v_tangential;
        const double limit = mu * std::abs(normal_force), magnitude = f.norm();
        if (magnitude > limit) {  // sliding: cap at μF_n, spring consistent with the capped force
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
    void release(State& s, Lost& lost) const {
        if (s.stiffness == 0) return;  // nothing held (the common case: a listed pair apart)
        lost.spring_stiffness += 0.5 * s.stiffness * s.spring.squaredNorm();
        s = {};
    }

    // ½ S_t |ξ|², J.
    double stored_energy(const ContactPair& c, const State& s) const {
        return c.overlap > 0 ? 0.5 * stiffness(c) * s.spring.squaredNorm() : 0.0;
    }
};

}  // namespace demscale::dem
