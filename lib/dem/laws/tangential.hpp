// Tangential contact laws.
//  TangentialNone  — frictionless: no state, no code in the force loop.
//  TangentialMindlin — incremental spring with history (Mindlin & Deresiewicz 1953 no-slip stiffness
//    S_t = 8 G* √(R* δ)), damping −2√(5/6) β √(S_t m*) v_t, Coulomb limit |F_t| ≤ μ F_n; on sliding
//    the spring is reset to the limit (as in LIGGGHTS' tangential_history). SI units.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct TangentialNone {
    struct State {};
    explicit TangentialNone(const Material&) {}
    Vec3 force(const ContactPair&, double, State&) const { return Vec3::Zero(); }
};

struct TangentialMindlin {
    struct State {
        Vec3 spring = Vec3::Zero();  // accumulated tangential displacement ξ, m
    };
    double g_star, beta, mu;

    explicit TangentialMindlin(const Material& m)
        : g_star(effective_shear(m)), beta(damping_ratio(m.restitution)), mu(m.friction) {}

    // normal_force: the total normal force (for the Coulomb limit).
    Vec3 force(const ContactPair& c, double normal_force, State& s) const {
        // Keep the spring in the current tangent plane, at its length (the pair may have rotated).
        const double length = s.spring.norm();
        s.spring -= c.normal * c.normal.dot(s.spring);
        const double projected = s.spring.norm();
        if (projected > 0) s.spring *= length / projected;
        s.spring += c.v_tangential * c.dt;
        const double st = 8.0 * g_star * std::sqrt(c.r_eff * c.overlap);
        const double damping = -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(st * c.m_eff);
        Vec3 f = -st * s.spring - damping * c.v_tangential;
        const double limit = mu * std::abs(normal_force), magnitude = f.norm();
        if (magnitude > limit) {  // sliding: cap at μF_n, spring consistent with the capped force
            f *= limit / magnitude;
            s.spring = st > 0 ? Vec3(-f / st) : Vec3::Zero();
        }
        return f;
    }
};

}  // namespace demscale::dem
