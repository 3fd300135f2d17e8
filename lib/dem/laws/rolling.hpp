// Rolling resistance.
//  RollingNone — free rolling: no state, no code in the force loop.
//  RollingConstantTorque — Ai, Chen, Rotter & Ooi (2011), model type A (constant directional
//    torque, LIGGGHTS' cdt): M = −μ_r R* |F_n| ω_roll/|ω_roll|. No state; at rest the torque flips
//    with ω every step, so a stopped sphere chatters (Ai et al.'s known drawback of model A).
//    Ledger: loses μ_r R* |F_n| |ω_roll| dt.
//  RollingEpsd — elastic–plastic spring–dashpot of Ai, Chen, Rotter & Ooi (2011), model type C,
//    without its viscous part (as LIGGGHTS' epsd2): k_r = 2.25 k_n μ_r² R*² (k_n = F_n/δ), incremental torque
//    ΔM = −k_r ω_roll dt with ω_roll the relative angular velocity in the tangent plane, and the
//    plastic limit |M| ≤ μ_r R* F_n. Torque on i is M, on j is −M. SI units.
//    Ledger: a step at the limit loses the work −M·Δθ less the spring's energy change; the stiffness
//    change is booked apart.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/energy.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct RollingNone {
    struct State {};
    explicit RollingNone(const Material&) {}
    template <class Lost>
    Vec3 torque(const ContactPair&, double, double, State&, Lost&) const { return Vec3::Zero(); }
    double stored_energy(const ContactPair&, double, const State&) const { return 0.0; }
    template <class Lost>
    void release(State&, Lost&) const {}
};

struct RollingConstantTorque {
    struct State {};
    double mu_r;
    explicit RollingConstantTorque(const Material& m) : mu_r(m.rolling_friction) {}
    template <class Lost>
    Vec3 torque(const ContactPair& c, double, double normal_force, State&, Lost& lost) const {
        const Vec3 w_roll = c.w_rel - c.normal * c.normal.dot(c.w_rel);  // twisting excluded
        const double w = w_roll.norm();
        if (w == 0) return Vec3::Zero();
        const double magnitude = mu_r * c.r_eff * std::abs(normal_force);
        lost.rolling += magnitude * w * c.dt;
        return -magnitude / w * w_roll;
    }
    double stored_energy(const ContactPair&, double, const State&) const { return 0.0; }
    template <class Lost>
    void release(State&, Lost&) const {}
};

struct RollingEpsd {
    struct State {
        Vec3 torque = Vec3::Zero();  // elastic rolling torque carried between steps, N m
        double stiffness = 0;        // k_r at the last step, N m/rad (for the ledger)
    };
    double mu_r;

    explicit RollingEpsd(const Material& m) : mu_r(m.rolling_friction) {}

    double stiffness(const ContactPair& c, double normal_stiffness) const {
        return 2.25 * normal_stiffness * mu_r * mu_r * c.r_eff * c.r_eff;
    }

    // normal_stiffness: secant k_n = F_el/δ of the normal law at this overlap (N/m); normal_force: F_n (N);
    // lost: what this step dissipates is added.
    template <class Lost>
    Vec3 torque(const ContactPair& c, double normal_stiffness, double normal_force, State& s, Lost& lost) const {
        const Vec3 w_roll = c.w_rel - c.normal * c.normal.dot(c.w_rel);  // twisting excluded
        const double kr = stiffness(c, normal_stiffness);
        s.torque -= c.normal * c.normal.dot(s.torque);  // keep it in the tangent plane
        const double before = s.torque.squaredNorm();
        if (s.stiffness > 0 && kr > 0) lost.spring_stiffness += 0.5 * before * (kr - s.stiffness) / (s.stiffness * kr);
        s.stiffness = kr;
        s.torque -= kr * c.dt * w_roll;
        const double limit = mu_r * c.r_eff * std::abs(normal_force), magnitude = s.torque.norm();
        if (magnitude > limit) {  // full mobilisation: plastic rolling
            s.torque *= limit / magnitude;
            lost.rolling += -s.torque.dot(w_roll) * c.dt - (kr > 0 ? 0.5 * (s.torque.squaredNorm() - before) / kr : 0.0);
        }
        return s.torque;
    }

    // The surfaces parted: the spring lets go of what it held.
    template <class Lost>
    void release(State& s, Lost& lost) const {
        if (s.stiffness == 0) return;  // nothing held
        lost.spring_stiffness += 0.5 * s.torque.squaredNorm() / s.stiffness;
        s = {};
    }

    // ½ |M|² / k_r, J.
    double stored_energy(const ContactPair& c, double normal_stiffness, const State& s) const {
        const double kr = stiffness(c, normal_stiffness);
        return kr > 0 ? 0.5 * s.torque.squaredNorm() / kr : 0.0;
    }
};

}  // namespace demscale::dem
