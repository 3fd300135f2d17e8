// Rolling resistance.
//  RollingNone — free rolling: no state, no code in the force loop.
//  RollingEpsd — elastic–plastic spring–dashpot of Ai, Chen, Rotter & Ooi (2011), model type C,
//    without its viscous part (as LIGGGHTS' epsd2): k_r = 2.25 k_n μ_r² R*² (k_n = F_n/δ), incremental torque
//    ΔM = −k_r ω_roll dt with ω_roll the relative angular velocity in the tangent plane, and the
//    plastic limit |M| ≤ μ_r R* F_n. Torque on i is M, on j is −M. SI units.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct RollingNone {
    struct State {};
    explicit RollingNone(const Material&) {}
    Vec3 torque(const ContactPair&, double, double, State&) const { return Vec3::Zero(); }
};

struct RollingEpsd {
    struct State {
        Vec3 torque = Vec3::Zero();  // elastic rolling torque carried between steps, N m
    };
    double mu_r;

    explicit RollingEpsd(const Material& m) : mu_r(m.rolling_friction) {}

    // normal_stiffness: secant k_n = F_el/δ of the normal law at this overlap (N/m); normal_force: F_n (N).
    Vec3 torque(const ContactPair& c, double normal_stiffness, double normal_force, State& s) const {
        const Vec3 w_roll = c.w_rel - c.normal * c.normal.dot(c.w_rel);  // twisting excluded
        const double kr = 2.25 * normal_stiffness * mu_r * mu_r * c.r_eff * c.r_eff;
        s.torque -= c.normal * c.normal.dot(s.torque);  // keep it in the tangent plane
        s.torque -= kr * c.dt * w_roll;
        const double limit = mu_r * c.r_eff * std::abs(normal_force), magnitude = s.torque.norm();
        if (magnitude > limit) s.torque *= limit / magnitude;  // full mobilisation: plastic rolling
        return s.torque;
    }
};

}  // namespace demscale::dem
