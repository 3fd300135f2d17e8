// Cohesion laws.
//  CohesionNone — dry: zero range, no state, no code in the force loop.
//  CohesionLiquidBridge — static pendular liquid bridge: a bridge forms when two surfaces touch,
//    pulls with F = force_scale·R·γ·F̂(ĥ) (ĥ = gap/R) while the gap stays below the rupture distance
//    ĥ_c·R, and is gone until the surfaces touch again. F̂ is a bridge::BridgeCurve: Mikami et al.'s
//    (1998) regression or the exact Young–Laplace bridge tabulated at the scene's V̂ and θ.
//    R is the spheres' common radius, or (per_pair, unequal spheres) the pair's harmonic mean
//    R* = 2 R_i R_j / (R_i + R_j) (Willett et al. 2000) in the force and in the rupture gap ĥ_c R*;
//    V̂ = V/R³ the same for every pair, so each bridge holds V = V̂ R*³ (Eq. 5 of Yun & Park 2017
//    with the pair's R*; docs/models/liquid-bridge.md); F̂ at contact computed once: a touching pair
//    costs nothing, one across a gap one curve evaluation.
//    Walls take their own curve (sphere–plane) when wet, no bridge when dry.
//    Ledger: a bridge's potential is minus the work to pull it to rupture (F̂ integrated); it
//    appears at contact with that negative value, so each formation books the same amount as lost.
//    Viscous part (optional, viscosity > 0): the normal lubrication force of a liquid bridge,
//    F_v = 6π μ R*² v_n / s · (1 − 1/√(1 + V/(π R* s²)))² (Pitois, Moucheront & Chateau 2000: the
//    Reynolds film squeezed only where the bridge's volume V wets; docs/models/bridge-viscous.md),
//    or, unbounded, without the bracket (the s ≪ R, V → ∞ limit; the normal part of LIGGGHTS'
//    easo/capillary/viscous). s = max(gap, s_min), s_min the surface roughness; it pulls a
//    separating pair together and pushes an approaching one apart, while a bridge holds.
//    With it the tangential lubrication force F_t = −6π μ R* (8/15 ln(R*/s) + 0.9588) v_t (Goldman,
//    Cox & Brenner 1967 for a sphere sliding past a plane, s ≪ R; the tangential part of
//    easo/capillary/viscous, after Nase et al. 2001), v_t the sliding velocity at the contact point.
//    R* = R/2 sphere–sphere, R at a wall. Ledger: F_v v_n dt + |F_t||v_t| dt ≥ 0 is the bridge's loss.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "bridge/bridge_curve.hpp"
#include "dem/contact_pair.hpp"
#include "dem/law_part.hpp"
#include "dem/energy.hpp"

namespace demscale::dem {

struct CohesionNone {
    struct State {};
    template <class Lost>
    using StateFor = State;
    double range() const { return 0.0; }
    template <class Lost>
    double pull(double, double, double, double, bool, State&, Lost&) const { return 0.0; }
    double stored_energy(const ContactPair&, const State&) const { return 0.0; }
    bool holds(const State&) const { return false; }
    bool needs_gap_velocity() const { return false; }
    template <class Lost>
    Vec3 drag(double, double, const Vec3&, double, bool, const State&, Lost&) const { return Vec3::Zero(); }
};

// Which R a bridge takes: the particles' common radius (monodisperse fills: the pair's radii are
// never read, so the force loop pays nothing for them), or each pair's harmonic mean.
enum class BridgeRadius { common, per_pair };

template <BridgeRadius Radius = BridgeRadius::common>
struct LiquidBridge {
    struct State {
        bool bridged = false;
    };
    template <class Lost>
    using StateFor = State;
    bridge::BridgeCurve k;                          // sphere–sphere
    double radius;                                  // the largest particle radius, m: sets the range
    double gamma;                                   // surface tension, N/m
    std::optional<bridge::BridgeCurve> wall;        // sphere–wall; nullopt: dry walls
    double viscosity = 0;                           // μ of the liquid, Pa s; 0: no viscous part
    double min_gap = 0;                             // s_min, m (roughness: the gap of touching surfaces)
    Lubrication lubrication = Lubrication::unbounded;  // the normal lubrication's form
    double vhat = 0;                                // V/R³ of every bridge (finite_volume reads it)

    // The wet settings' bridge for particles of these sizes: dem/bridge_law.cpp.
    static LiquidBridge build(const ContactSettings& s, const LawSizes& sizes, const std::string& where);

    // per_pair: each pair's bridge has R = its harmonic-mean radius 2 R_i R_j / (R_i + R_j) (R_i at
    // a wall; Mikami et al. 1998, Willett et al. 2000) and the same V̂ = V/R³: the liquid of Eq. 5
    // per bridge grows with the pair's mass. With equal radii both give the same bits.
    LiquidBridge(bridge::BridgeCurve sphere, double radius_m, double gamma_n_per_m, std::optional<bridge::BridgeCurve> wall_curve,
                 double viscosity_pa_s = 0, double min_gap_m = 0, Lubrication lubrication_form = Lubrication::unbounded,
                 double bridge_vhat = 0)
        : k(std::move(sphere)), radius(radius_m), gamma(gamma_n_per_m), wall(std::move(wall_curve)), viscosity(viscosity_pa_s),
          min_gap(min_gap_m), lubrication(lubrication_form), vhat(bridge_vhat), fhat0_(k.fhat(0.0)), fhat0_wall_(wall ? wall->fhat(0.0) : 0.0),
          touching_(k.force_scale() * radius_m * gamma_n_per_m * fhat0_),
          touching_wall_(wall ? wall->force_scale() * radius_m * gamma_n_per_m * fhat0_wall_ : 0.0),
          drag_touching_(drag_coefficient(0.5 * radius_m, min_gap_m)), drag_touching_wall_(drag_coefficient(radius_m, min_gap_m)) {}

    // Whether the engine must give pull() and drag() the velocities of a pair across a gap.
    bool needs_gap_velocity() const { return viscosity > 0; }

    // The bridge's R for a pair whose harmonic-mean radius is r, m.
    DEMSCALE_HOT double bridge_radius(double r) const {
        if constexpr (Radius == BridgeRadius::per_pair) return r;
        else return radius;
    }

    // Whether a bridge holds this pair: across a gap, nothing else can act on it.
    bool holds(const State& s) const { return s.bridged; }

    // Range beyond contact over which a bridge still acts: the rupture gap, m.
    double range() const { return std::max(k.hhat_rupture(), wall ? wall->hhat_rupture() : 0.0) * radius; }

    // Attractive force magnitude (N) along −n on particle i, at overlap δ (m, < 0 a gap) with a
    // sphere or a wall, r the pair's harmonic-mean radius (m), the pair separating at v_normal (m/s,
    // > 0 apart; read only with a viscous part) over a step dt (s, for the ledger); lost: what this
    // step dissipates is added. Needs no more of the pair than δ, r and v_n.
    template <class Lost>
    DEMSCALE_HOT double pull(double overlap, double pair_r, double v_normal, double dt, bool with_wall, State& s, Lost& lost) const {
        const double r = bridge_radius(pair_r);
        const double capillary = static_pull(overlap, r, with_wall, s, lost);
        if (viscosity <= 0 || !s.bridged || (with_wall && !wall)) return capillary;
        // 6π μ R*² with R* = r/2 (sphere–sphere) or r (wall), in the order that keeps equal radii's bits.
        const double squeeze = with_wall ? 6 * M_PI * viscosity * r * r : 6 * M_PI * viscosity * 0.25 * r * r;
        const double s_gap = std::max(-overlap, min_gap);
        double viscous = squeeze * v_normal / s_gap;
        if (lubrication == Lubrication::finite_volume) viscous *= finite_volume_factor(r, s_gap, with_wall);
        lost.bridge += viscous * v_normal * dt;
        return capillary + viscous;
    }

    // The tangential lubrication force on particle i (N), sliding at v_tangential (m/s, i relative to
    // j at the contact point) at overlap δ (m, < 0 a gap), r the pair's harmonic-mean radius (m),
    // while the bridge (state s, as pull() left it this step) holds; zero without a viscous part.
    // lost: F_t·v_t dt is added.
    template <class Lost>
    DEMSCALE_HOT Vec3 drag(double overlap, double pair_r, const Vec3& v_tangential, double dt, bool with_wall, const State& s,
                           Lost& lost) const {
        const double r = bridge_radius(pair_r);
        if (viscosity <= 0 || !s.bridged || (with_wall && !wall)) return Vec3::Zero();
        const double r_star = with_wall ? r : 0.5 * r;
        const double coefficient = overlap >= -min_gap && r == radius ? (with_wall ? drag_touching_wall_ : drag_touching_)
                                                                      : drag_coefficient(r_star, std::max(-overlap, min_gap));
        lost.bridge += coefficient * v_tangential.squaredNorm() * dt;
        return -coefficient * v_tangential;
    }

    // Potential energy of this pair's bridge, J (≤ 0; 0 without a bridge).
    double stored_energy(const ContactPair& c, const State& s) const {
        if (!s.bridged || (c.wall && !wall)) return 0.0;
        return potential(c.wall ? *wall : k, bridge_radius(c.r_harmonic), c.overlap);
    }

private:
    // The static bridge: Eq. 1 (Yun & Park 2017) with the curve's F̂.
    template <class Lost>
    DEMSCALE_HOT double static_pull(double overlap, double r, bool with_wall, State& s, Lost& lost) const {
        if (with_wall && !wall) return 0.0;
        const bridge::BridgeCurve& law = with_wall ? *wall : k;
        if (overlap >= 0) {  // touching: a bridge forms if there was none, and pulls with F(ĥ = 0)
            if (!s.bridged) {
                s.bridged = true;
                lost.bridge -= potential(law, r, overlap);
            }
            if (Radius == BridgeRadius::common || r == radius) return with_wall ? touching_wall_ : touching_;
            return law.force_scale() * r * gamma * (with_wall ? fhat0_wall_ : fhat0_);
        }
        if (!s.bridged) return 0.0;
        const double hhat = -overlap / r;
        if (hhat > law.hhat_rupture()) {  // ruptured: gone until the next contact
            s.bridged = false;
            return 0.0;
        }
        return law.force_scale() * r * gamma * law.fhat(hhat);  // Eq. 1, N
    }

    // F̂ at contact, computed once: F̂ holds its ĥ = 0 value under any overlap, so most of a wet
    // pile's pairs, which touch, need no curve evaluation.
    double fhat0_, fhat0_wall_;
    double touching_, touching_wall_;  // the force at contact for r = radius, N
    double drag_touching_, drag_touching_wall_;  // drag_coefficient at s = s_min for r = radius, N s/m

    // 6π μ R* (8/15 ln(R*/s) + 0.9588), N s/m, with s = max(gap, s_min); never negative (the
    // bracket would turn at s ≈ 6 R*, far beyond any rupture gap).
    double drag_coefficient(double r_star, double gap) const {
        const double s = std::max(gap, min_gap);
        return 6 * M_PI * viscosity * r_star * std::max(0.0, 8.0 / 15.0 * std::log(r_star / s) + 0.9588);
    }

    // (1 − s/H)² of Pitois et al. (2000): the film is squeezed out to the meniscus, where the gap is
    // H; a bridge of volume V on a sphere of R* (a plane opposite) has V = π R* (H² − s²). V = V̂ r³;
    // R* = r/2 between spheres, r at a wall. 1 as V → ∞.
    DEMSCALE_HOT double finite_volume_factor(double r, double s, bool with_wall) const {
        const double wetted = (with_wall ? 1.0 : 2.0) * vhat * r * r / (M_PI * s * s);  // V / (π R* s²)
        const double f = 1 - 1 / std::sqrt(1 + wetted);
        return f * f;
    }

    double potential(const bridge::BridgeCurve& law, double r, double overlap) const {
        return -law.force_scale() * r * r * gamma * law.work_to_rupture(-overlap / r);
    }
};

using CohesionLiquidBridge = LiquidBridge<BridgeRadius::common>;
using CohesionLiquidBridgePerPair = LiquidBridge<BridgeRadius::per_pair>;

// Parameters of the static bridge (docs/models/liquid-bridge.md): γ is the candidate of the
// similarity (γ̄ = γ·S_f^k, Eq. 12); the liquid per bridge follows the particle mass (Eq. 5).
inline constexpr Parameter bridge_parameters[] = {
    {"liquid.surface_tension_n_per_m", "surface tension gamma", "N/m", {3, 1, -2}, 0.074, {0, unbounded}, Replacement::surface_tension, {},
     {}, LiggghtsKind::scalar, [](const ContactSettings& s) { return s.liquid.surface_tension_n_per_m; },
     [](ContactSettings& s, double x) { s.liquid.surface_tension_n_per_m = x; }},
    {"liquid.contact_angle_deg", "contact angle theta", "deg", {}, 0, {0, 90, false, true}, Replacement::kept, {}, {},
     LiggghtsKind::scalar, [](const ContactSettings& s) { return s.liquid.contact_angle.degrees(); },
     [](ContactSettings& s, double x) { s.liquid.contact_angle = ContactAngle(Degrees{x}); }},
    {"liquid.density_kg_per_m3", "liquid density", "kg/m^3", {0, 1, 0}, 1000, {0, unbounded}, Replacement::kept, {}, {},
     LiggghtsKind::scalar, [](const ContactSettings& s) { return s.liquid.density_kg_per_m3; },
     [](ContactSettings& s, double x) { s.liquid.density_kg_per_m3 = x; }},
    {"liquid.moisture_content", "moisture content (Eq. 5)", "kg/kg", {}, 0.045, {0, 1}, Replacement::kept, {}, {},
     LiggghtsKind::scalar, [](const ContactSettings& s) { return s.liquid.moisture_content; },
     [](ContactSettings& s, double x) { s.liquid.moisture_content = x; }},
};
// Chosen by liquid.wet (its curve by liquid.bridge_variant: bridge/curve_sources.hpp). LIGGGHTS
// refuses the bridge on walls, so its words go to the particle pair style only.
inline constexpr LawPart bridge_part{.name = "static liquid bridge (Mikami et al. 1998)",
                                     .parameters = bridge_parameters,
                                     .active = [](const ContactSettings& s) { return s.wet; },
                                     .liggghts_model = "cohesion easo/capillary/viscous",
                                     .slot = Slot::cohesion,
                                     .choice = "liquid_bridge",
                                     .choose = [](ContactSettings& s) { s.wet = true; },
                                     .liggghts_walls = false};

// Parameters of the bridge's viscous part (docs/models/bridge-viscous.md). μ is a viscosity: kept
// (the same liquid), or scaled by --scale viscosity.
inline constexpr Parameter bridge_viscous_parameters[] = {
    {"liquid.viscosity_pa_s", "liquid viscosity mu", "Pa s", {2, 1, -1}, 0, {0, 1000, false, false}, Replacement::scalable,
     "viscosity", {}, LiggghtsKind::scalar, [](const ContactSettings& s) { return s.viscosity_pa_s; },
     [](ContactSettings& s, double x) { s.viscosity_pa_s = x; }},
    {"liquid.min_gap_ratio", "lubrication gap of touching spheres s_min/R", "1", {}, 0.01, {0, 1}, Replacement::kept, {}, {},
     LiggghtsKind::scalar, [](const ContactSettings& s) { return s.min_gap_ratio; },
     [](ContactSettings& s, double x) { s.min_gap_ratio = x; }},
};
// The normal lubrication damps a pair with c = 6π μ R*² / s_min: an explicit step is stable below
// 2 m*/c, (8/9) ρ R² (s_min/R) / μ for equal spheres, half that at a wall (R* = R, m* = m).
inline constexpr LawPart bridge_viscous_part{
    "viscous part of the liquid bridge (normal lubrication, sliding drag)", bridge_viscous_parameters,
    [](const ContactSettings& s) { return s.wet && s.viscosity_pa_s > 0; },
    [](const ContactSettings& s, double radius) {
        const double pair = 8.0 / 9.0 * s.material.density * radius * radius * s.min_gap_ratio / s.viscosity_pa_s;
        return TimeScale{s.wet_walls ? pair / 2 : pair, 0.2, "the lubrication time 2 m*/c"};
    },
    {}, {}, {}, nullptr, {}, Slot::cohesion};

}  // namespace demscale::dem
