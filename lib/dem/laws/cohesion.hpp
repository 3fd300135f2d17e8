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
#pragma once

#include <algorithm>
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
    double pull(double, bool, State&, Lost&) const { return 0.0; }
    double stored_energy(const ContactPair&, const State&) const { return 0.0; }
    bool holds(const State&) const { return false; }
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

    CohesionMikamiBridge(bridge::MikamiCoefficients sphere, double radius_m, double gamma_n_per_m,
                         std::optional<bridge::MikamiCoefficients> wall_coefficients)
        : k(sphere), radius(radius_m), gamma(gamma_n_per_m), wall(wall_coefficients),
          touching_(bridge_force(k, 0.0)), touching_wall_(wall ? bridge_force(*wall, 0.0) : 0.0) {}

    // Whether a bridge holds this pair: across a gap, nothing else can act on it.
    bool holds(const State& s) const { return s.bridged; }

    // Range beyond contact over which a bridge still acts: the rupture gap, m.
    double range() const { return std::max(k.hhat_rupture, wall ? wall->hhat_rupture : 0.0) * radius; }

    // Attractive force magnitude (N) along −n on particle i, at overlap δ (m, < 0 a gap) with a
    // sphere or a wall; lost: what this step dissipates is added. Needs no more of the pair than δ.
    template <class Lost>
    DEMSCALE_HOT double pull(double overlap, bool with_wall, State& s, Lost& lost) const {
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

    // Potential energy of this pair's bridge, J (≤ 0; 0 without a bridge).
    double stored_energy(const ContactPair& c, const State& s) const {
        if (!s.bridged || (c.wall && !wall)) return 0.0;
        return potential(c.wall ? *wall : k, c.overlap);
    }

private:
    // Eq. 1 with Eq. 2: F = force_scale·R·γ·F̂(ĥ), N.
    double bridge_force(const bridge::MikamiCoefficients& law, double hhat) const {
        return law.force_scale * radius * gamma * bridge::mikami_fhat(law, hhat);
    }
    // The force at contact, computed once: F̂ holds its ĥ = 0 value under any overlap (mikami_fhat),
    // so most of a wet pile's pairs, which touch, need no exp.
    double touching_, touching_wall_;

    double potential(const bridge::MikamiCoefficients& law, double overlap) const {
        return -law.force_scale * radius * radius * gamma * bridge::mikami_work_to_rupture(law, -overlap / radius);
    }
};

}  // namespace demscale::dem
