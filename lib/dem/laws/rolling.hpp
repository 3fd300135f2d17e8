// Rolling resistance. Laws get the contact, the normal law's secant stiffness k_n = F_el/δ, the
// tangential law's stiffness k_t and the normal force F_n (N/m, N/m, N). SI units.
//  RollingNone — free rolling: no state, no code in the force loop.
//  RollingConstantTorque — Ai, Chen, Rotter & Ooi (2011), model type A (constant directional
//    torque, LIGGGHTS' cdt): M = −μ_r R* F_el ω_roll/|ω_roll|, with the elastic normal force
//    F_el = k_n δ as cdt uses. No state; at rest the torque flips with ω every step, so a stopped
//    sphere chatters (Ai et al.'s known drawback of model A). Ledger: loses |M| |ω_roll| dt.
//  RollingSpring<Stiffness> — elastic–plastic rolling spring with an optional dashpot: incremental
//    torque ΔM = −k_r ω_roll dt, ω_roll the relative angular velocity in the tangent plane, plastic
//    limit |M| ≤ μ_r R* |F_n|. Ai et al. (2011), model type C, adds the dashpot M_d = −C_r ω_roll,
//    C_r = η_r · 2√(I_r k_r) with η_r = Material::rolling_damping (0: no dashpot) and I_r the pair's
//    rolling inertia; it acts only below full mobilisation (their f = 0, as LIGGGHTS). Torque on i
//    is M + M_d, on j the opposite. Two stiffness rules:
//      RollingEpsd  — Ai et al. (2011), model type C: k_r = 2.25 k_n μ_r² R*² (LIGGGHTS' epsd3 with
//                     rollingStiffness 2.25 and coefficientRollingViscousDamping η_r).
//      RollingEpsd2 — Iwashita & Oda (1998), LIGGGHTS' epsd2: k_r = k_t R*² (scenes give it no dashpot,
//                     as LIGGGHTS).
//    Ledger: a step at the limit loses the work −M·Δθ less the spring's energy change; the dashpot
//    loses C_r |ω_roll|² dt; the stiffness change is booked apart.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/law_part.hpp"
#include "dem/energy.hpp"
#include "dem/laws/plastic_limit.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct RollingNone {
    struct State {};
    template <class Lost>
    using StateFor = State;
    explicit RollingNone(const Material&) {}
    template <class Lost>
    Vec3 torque(const ContactPair&, double, double, double, State&, Lost&) const { return Vec3::Zero(); }
    double stored_energy(const ContactPair&, double, double, const State&) const { return 0.0; }
    template <class Lost>
    void release(State&, Lost&) const {}
};

struct RollingConstantTorque {
    struct State {};
    template <class Lost>
    using StateFor = State;
    double mu_r;
    explicit RollingConstantTorque(const Material& m) : mu_r(m.rolling_friction) {}
    template <class Lost>
    Vec3 torque(const ContactPair& c, double normal_stiffness, double, double, State&, Lost& lost) const {
        const Vec3 w_roll = c.w_rel - c.normal * c.normal.dot(c.w_rel);  // twisting excluded
        const double w = w_roll.norm();
        if (w == 0) return Vec3::Zero();
        const double magnitude = mu_r * c.r_eff * normal_stiffness * c.overlap;
        lost.rolling += magnitude * w * c.dt;
        return -magnitude / w * w_roll;
    }
    double stored_energy(const ContactPair&, double, double, const State&) const { return 0.0; }
    template <class Lost>
    void release(State&, Lost&) const {}
};

// A rolling spring's history. Lost = Dissipation: with the ledger's k_r of the last step; NoDissipation: without.
template <class Lost>
struct RollingSpringState {
    Vec3 torque = Vec3::Zero();                          // elastic rolling torque carried between steps, N m
    [[no_unique_address]] LastStiffness<Lost> stiffness; // k_r at the last step, N m/rad
};

template <class Stiffness>
struct RollingSpring {
    template <class Lost>
    using StateFor = RollingSpringState<Lost>;
    using State = StateFor<Dissipation>;
    double mu_r, eta_r;

    explicit RollingSpring(const Material& m) : mu_r(m.rolling_friction), eta_r(m.rolling_damping) {}

    double stiffness(const ContactPair& c, double normal_stiffness, double tangential_stiffness) const {
        return Stiffness::of(c, normal_stiffness, tangential_stiffness, mu_r);
    }

    // lost: what this step dissipates is added.
    template <class Lost>
    DEMSCALE_HOT Vec3 torque(const ContactPair& c, double normal_stiffness, double tangential_stiffness, double normal_force,
                             StateFor<Lost>& s, Lost& lost) const {
        const Vec3 w_roll = c.w_rel - c.normal * c.normal.dot(c.w_rel);  // twisting excluded
        const double kr = stiffness(c, normal_stiffness, tangential_stiffness);
        s.torque -= c.normal * c.normal.dot(s.torque);  // keep it in the tangent plane
        const double before = s.torque.squaredNorm();
        if constexpr (books_losses<Lost>) {
            const double was = s.stiffness.value;
            if (was > 0 && kr > 0) lost.spring_stiffness += 0.5 * before * (kr - was) / (was * kr);
            s.stiffness.value = kr;
        }
        s.torque -= kr * c.dt * w_roll;
        const double limit = mu_r * c.r_eff * std::abs(normal_force);
        if (const double magnitude = beyond_limit(s.torque.squaredNorm(), limit)) {  // full mobilisation: plastic rolling
            s.torque *= limit / magnitude;
            lost.rolling += -s.torque.dot(w_roll) * c.dt - (kr > 0 ? 0.5 * (s.torque.squaredNorm() - before) / kr : 0.0);
        } else if (eta_r > 0 && c.rolling_compliance > 0) {  // dashpot below full mobilisation only (Ai et al. 2011, f = 0)
            const double c_r = eta_r * 2.0 * std::sqrt(kr / c.rolling_compliance);  // C_r = η_r 2√(I_r k_r)
            lost.rolling += c_r * w_roll.squaredNorm() * c.dt;
            return s.torque - c_r * w_roll;
        }
        return s.torque;
    }

    // The surfaces parted: the spring lets go of what it held.
    template <class Lost>
    void release(StateFor<Lost>& s, Lost& lost) const {
        if constexpr (books_losses<Lost>) {
            if (s.stiffness.value == 0) return;  // nothing held
            lost.spring_stiffness += 0.5 * s.torque.squaredNorm() / s.stiffness.value;
        }
        s = {};
    }

    // ½ |M|² / k_r, J.
    template <class Lost>
    double stored_energy(const ContactPair& c, double normal_stiffness, double tangential_stiffness, const StateFor<Lost>& s) const {
        const double kr = stiffness(c, normal_stiffness, tangential_stiffness);
        return kr > 0 ? 0.5 * s.torque.squaredNorm() / kr : 0.0;
    }
};

// k_r = 2.25 k_n μ_r² R*² (Ai et al. 2011, model type C).
struct AiRollingStiffness {
    static double of(const ContactPair& c, double k_n, double, double mu_r) { return 2.25 * k_n * mu_r * mu_r * c.r_eff * c.r_eff; }
};
// k_r = k_t R*² (Iwashita & Oda 1998; LIGGGHTS' epsd2).
struct IwashitaOdaRollingStiffness {
    static double of(const ContactPair& c, double, double k_t, double) { return k_t * c.r_eff * c.r_eff; }
};

using RollingEpsd = RollingSpring<AiRollingStiffness>;
using RollingEpsd2 = RollingSpring<IwashitaOdaRollingStiffness>;

// The scene's rolling law (RollingModel), chosen at run time: one compiled engine serves all three,
// each model's arithmetic unchanged (the same bits as the law compiled alone). The choice costs
// 0.6-2.2 % more instructions than RollingEpsd compiled alone (docs/performance.md), so the slump
// engines keep that one apart; a constant-torque run carries the spring's unused history (24 bytes
// a pair, 32 with the ledger).
struct RollingChosen {
    template <class Lost>
    using StateFor = RollingSpringState<Lost>;
    using State = StateFor<Dissipation>;
    RollingModel model;
    RollingEpsd epsd;
    RollingEpsd2 epsd2;
    RollingConstantTorque constant;
    double eta_r;  // the chosen law's dashpot η_r (constant torque has none): the engine sets I_r from it

    RollingChosen(const Material& m, RollingModel chosen)
        : model(chosen), epsd(m), epsd2(m), constant(m), eta_r(chosen == RollingModel::constant_torque ? 0.0 : m.rolling_damping) {}
    static RollingChosen build(const ContactSettings& s, const LawSizes&, const std::string&) { return {s.material, s.rolling_model}; }

    template <class Lost>
    DEMSCALE_HOT Vec3 torque(const ContactPair& c, double normal_stiffness, double tangential_stiffness, double normal_force,
                             StateFor<Lost>& s, Lost& lost) const {
        if (model == RollingModel::epsd) return epsd.torque(c, normal_stiffness, tangential_stiffness, normal_force, s, lost);
        if (model == RollingModel::epsd2) return epsd2.torque(c, normal_stiffness, tangential_stiffness, normal_force, s, lost);
        RollingConstantTorque::State stateless;
        return constant.torque(c, normal_stiffness, tangential_stiffness, normal_force, stateless, lost);
    }
    // Constant torque leaves the spring's history at zero, so the spring's release books nothing for it.
    template <class Lost>
    void release(StateFor<Lost>& s, Lost& lost) const { epsd.release(s, lost); }
    template <class Lost>
    double stored_energy(const ContactPair& c, double normal_stiffness, double tangential_stiffness, const StateFor<Lost>& s) const {
        if (model == RollingModel::epsd) return epsd.stored_energy(c, normal_stiffness, tangential_stiffness, s);
        if (model == RollingModel::epsd2) return epsd2.stored_energy(c, normal_stiffness, tangential_stiffness, s);
        return 0.0;
    }
};

// Parameters (docs/models/rolling.md): μ_r for every rolling model; η_r for Ai's dashpot (epsd).
inline constexpr Parameter rolling_parameters[] = {
    {"contact.rolling_friction", "rolling friction", "1", {}, 0.1, {0, 10}, Replacement::kept, {}, "coefficientRollingFriction",
     LiggghtsKind::per_type_pair, [](const ContactSettings& s) { return s.material.rolling_friction; },
     [](ContactSettings& s, double x) { s.material.rolling_friction = x; }},
};
// Its law (epsd, epsd2 or constant torque: contact.rolling_model) is chosen at run time or by
// the engine list (slump/compiled_engines.hpp), so this part is the slot's parameter group.
inline constexpr LawPart rolling_part{.name = "rolling resistance",
                                      .parameters = rolling_parameters,
                                      .active = [](const ContactSettings& s) { return s.rolling_resistance; },
                                      .slot = Slot::rolling};

inline constexpr Parameter rolling_dashpot_parameters[] = {
    {"contact.rolling_damping", "rolling damping eta_r", "1", {}, 0.3, {0, 1, false, false}, Replacement::kept, {},
     "coefficientRollingViscousDamping", LiggghtsKind::per_type_pair,
     [](const ContactSettings& s) { return s.material.rolling_damping; },
     [](ContactSettings& s, double x) { s.material.rolling_damping = x; }},
};
// LIGGGHTS' epsd3 is Ai's model C with the stiffness prefactor stated apart.
inline constexpr LawPart rolling_dashpot_part{
    "rolling spring and dashpot (Ai et al. 2011, model C)", rolling_dashpot_parameters,
    [](const ContactSettings& s) { return s.rolling_resistance && s.rolling_model == RollingModel::epsd; }, nullptr,
    "property/global rollingStiffness scalar 2.25", {}, {}, nullptr, {}, Slot::rolling};

}  // namespace demscale::dem
