// Cohesion laws.
//  CohesionNone — dry: zero range, no state, no code in the force loop.
//  CohesionMikamiBridge — static pendular liquid bridge (Mikami et al. 1998 via the bridge library):
//    a bridge forms when two surfaces touch, pulls with F = force_scale·R·γ·F̂(ĥ) (ĥ = gap/R) while
//    the gap stays below the rupture distance ĥ_c·R, and is gone until the surfaces touch again.
//    Equal spheres of radius R (monodisperse wet scenes); coefficients computed once, and the force
//    at contact too: a touching pair costs no exp, one across a gap one.
//    Walls use Mikami's sphere–wall coefficients when wet, no bridge when dry.
//    Ledger: a bridge's potential is minus the work to pull it to rupture (Eq. 2 integrated); it
//    appears at contact with that negative value, so each formation books the same amount as lost.
//    Viscous part (optional, viscosity > 0): the normal lubrication force of a liquid bridge,
//    F_v = 6π μ R*² v_n / s (Pitois, Moucheront & Chateau 2000, Eq. 3 for s ≪ R; the normal part
//    of LIGGGHTS' easo/capillary/viscous), s = max(gap, s_min), s_min the surface roughness; it
//    pulls a separating pair together and pushes an approaching one apart, while a bridge holds.
//    With it the tangential lubrication force F_t = −6π μ R* (8/15 ln(R*/s) + 0.9588) v_t (Goldman,
//    Cox & Brenner 1967 for a sphere sliding past a plane, s ≪ R; the tangential part of
//    easo/capillary/viscous, after Nase et al. 2001), v_t the sliding velocity at the contact point.
//    R* = R/2 sphere–sphere, R at a wall. Ledger: F_v v_n dt + |F_t||v_t| dt ≥ 0 is the bridge's loss.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "bridge/mikami.hpp"
#include "dem/contact_pair.hpp"
#include "dem/energy.hpp"

namespace demscale::dem {

struct CohesionNone {
    struct State {};
    template <class Lost>
    using StateFor = State;
    double range() const { return 0.0; }
    template <class Lost>
    double pull(double, double, double, bool, State&, Lost&) const { return 0.0; }
    double stored_energy(const ContactPair&, const State&) const { return 0.0; }
    bool holds(const State&) const { return false; }
    bool needs_gap_velocity() const { return false; }
    template <class Lost>
    Vec3 drag(double, const Vec3&, double, bool, const State&, Lost&) const { return Vec3::Zero(); }
};

struct CohesionMikamiBridge {
    struct State {
        bool bridged = false;
    };
    template <class Lost>
    using StateFor = State;
    bridge::MikamiCoefficients k;                   // sphere–sphere
    double radius;                                  // R of the equal spheres, m
    double gamma;                                   // surface tension, N/m
    std::optional<bridge::MikamiCoefficients> wall; // sphere–wall; nullopt: dry walls
    double viscosity = 0;                           // μ of the liquid, Pa s; 0: no viscous part
    double min_gap = 0;                             // s_min, m (roughness: the gap of touching surfaces)

    CohesionMikamiBridge(bridge::MikamiCoefficients sphere, double radius_m, double gamma_n_per_m,
                         std::optional<bridge::MikamiCoefficients> wall_coefficients, double viscosity_pa_s = 0,
                         double min_gap_m = 0)
        : k(sphere), radius(radius_m), gamma(gamma_n_per_m), wall(wall_coefficients), viscosity(viscosity_pa_s),
          min_gap(min_gap_m), touching_(bridge_force(k, 0.0)), touching_wall_(wall ? bridge_force(*wall, 0.0) : 0.0),
          lubrication_(6 * M_PI * viscosity_pa_s * 0.25 * radius_m * radius_m),
          lubrication_wall_(6 * M_PI * viscosity_pa_s * radius_m * radius_m),
          drag_touching_(drag_coefficient(0.5 * radius_m, min_gap_m)), drag_touching_wall_(drag_coefficient(radius_m, min_gap_m)) {}

    // Whether the engine must give pull() and drag() the velocities of a pair across a gap.
    bool needs_gap_velocity() const { return viscosity > 0; }

    // Whether a bridge holds this pair: across a gap, nothing else can act on it.
    bool holds(const State& s) const { return s.bridged; }

    // Range beyond contact over which a bridge still acts: the rupture gap, m.
    double range() const { return std::max(k.hhat_rupture, wall ? wall->hhat_rupture : 0.0) * radius; }

    // Attractive force magnitude (N) along −n on particle i, at overlap δ (m, < 0 a gap) with a
    // sphere or a wall, the pair separating at v_normal (m/s, > 0 apart; read only with a viscous
    // part) over a step dt (s, for the ledger); lost: what this step dissipates is added. Needs no
    // more of the pair than δ and v_n.
    template <class Lost>
    DEMSCALE_HOT double pull(double overlap, double v_normal, double dt, bool with_wall, State& s, Lost& lost) const {
        const double capillary = static_pull(overlap, with_wall, s, lost);
        if (viscosity <= 0 || !s.bridged || (with_wall && !wall)) return capillary;
        const double viscous = (with_wall ? lubrication_wall_ : lubrication_) * v_normal / std::max(-overlap, min_gap);
        lost.bridge += viscous * v_normal * dt;
        return capillary + viscous;
    }

    // The tangential lubrication force on particle i (N), sliding at v_tangential (m/s, i relative to
    // j at the contact point) at overlap δ (m, < 0 a gap) while the bridge (state s, as pull() left
    // it this step) holds; zero without a viscous part. lost: F_t·v_t dt is added.
    template <class Lost>
    DEMSCALE_HOT Vec3 drag(double overlap, const Vec3& v_tangential, double dt, bool with_wall, const State& s, Lost& lost) const {
        if (viscosity <= 0 || !s.bridged || (with_wall && !wall)) return Vec3::Zero();
        const double coefficient = overlap >= -min_gap ? (with_wall ? drag_touching_wall_ : drag_touching_)
                                                       : drag_coefficient(with_wall ? radius : 0.5 * radius, -overlap);
        lost.bridge += coefficient * v_tangential.squaredNorm() * dt;
        return -coefficient * v_tangential;
    }

    // Potential energy of this pair's bridge, J (≤ 0; 0 without a bridge).
    double stored_energy(const ContactPair& c, const State& s) const {
        if (!s.bridged || (c.wall && !wall)) return 0.0;
        return potential(c.wall ? *wall : k, c.overlap);
    }

private:
    // The static bridge: Eqs. 1-2 (Mikami et al. 1998).
    template <class Lost>
    DEMSCALE_HOT double static_pull(double overlap, bool with_wall, State& s, Lost& lost) const {
        if (with_wall && !wall) return 0.0;
        const bridge::MikamiCoefficients& law = with_wall ? *wall : k;
        if (overlap >= 0) {  // touching: a bridge forms if there was none, and pulls with F(ĥ = 0)
            if (!s.bridged) {
                s.bridged = true;
                lost.bridge -= potential(law, overlap);
            }
            return with_wall ? touching_wall_ : touching_;
        }
        if (!s.bridged) return 0.0;
        const double hhat = -overlap / radius;
        if (hhat > law.hhat_rupture) {  // ruptured: gone until the next contact
            s.bridged = false;
            return 0.0;
        }
        return bridge_force(law, hhat);
    }

    // Eq. 1 with Eq. 2: F = force_scale·R·γ·F̂(ĥ), N.
    double bridge_force(const bridge::MikamiCoefficients& law, double hhat) const {
        return law.force_scale * radius * gamma * bridge::mikami_fhat(law, hhat);
    }
    // The force at contact, computed once: F̂ holds its ĥ = 0 value under any overlap (mikami_fhat),
    // so most of a wet pile's pairs, which touch, need no exp.
    double touching_, touching_wall_;
    double lubrication_, lubrication_wall_;  // 6π μ R*², N s (sphere–sphere R* = R/2; wall R* = R)
    double drag_touching_, drag_touching_wall_;  // drag_coefficient at s = s_min, N s/m

    // 6π μ R* (8/15 ln(R*/s) + 0.9588), N s/m, with s = max(gap, s_min); never negative (the
    // bracket would turn at s ≈ 6 R*, far beyond any rupture gap).
    double drag_coefficient(double r_star, double gap) const {
        const double s = std::max(gap, min_gap);
        return 6 * M_PI * viscosity * r_star * std::max(0.0, 8.0 / 15.0 * std::log(r_star / s) + 0.9588);
    }

    double potential(const bridge::MikamiCoefficients& law, double overlap) const {
        return -law.force_scale * radius * radius * gamma * bridge::mikami_work_to_rupture(law, -overlap / radius);
    }
};

}  // namespace demscale::dem
