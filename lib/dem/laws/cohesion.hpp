// Cohesion laws.
//  CohesionNone — dry: zero range, no state, no code in the force loop.
//  CohesionMikamiBridge — static pendular liquid bridge (Mikami et al. 1998 via the bridge library):
//    a bridge forms when two surfaces touch, pulls with F = force_scale·R·γ·F̂(ĥ) (ĥ = gap/R) while
//    the gap stays below the rupture distance ĥ_c·R, and is gone until the surfaces touch again.
//    Equal spheres of radius R (monodisperse wet scenes); coefficients computed once (one exp per force).
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
    double range() const { return 0.0; }
    template <class Lost>
    double force(const ContactPair&, State&, Lost&) const { return 0.0; }
    double stored_energy(const ContactPair&, const State&) const { return 0.0; }
    bool holds(const State&) const { return false; }
};

struct CohesionMikamiBridge {
    struct State {
        bool bridged = false;
    };
    bridge::MikamiCoefficients k;                   // sphere–sphere
    double radius;                                  // R of the equal spheres, m
    double gamma;                                   // surface tension, N/m
    std::optional<bridge::MikamiCoefficients> wall; // sphere–wall; nullopt: dry walls

    // Whether a bridge holds this pair: across a gap, nothing else can act on it.
    bool holds(const State& s) const { return s.bridged; }

    // Range beyond contact over which a bridge still acts: the rupture gap, m.
    double range() const { return std::max(k.hhat_rupture, wall ? wall->hhat_rupture : 0.0) * radius; }

    // Attractive force magnitude (N) along −n on particle i; lost: what this step dissipates is added.
    template <class Lost>
    double force(const ContactPair& c, State& s, Lost& lost) const {
        if (c.wall && !wall) return 0.0;
        const bridge::MikamiCoefficients& law = c.wall ? *wall : k;
        if (c.overlap >= 0 && !s.bridged) {  // forms at contact
            s.bridged = true;
            lost.bridge -= potential(law, c);
        }
        if (!s.bridged) return 0.0;
        const double hhat = -c.overlap / radius;
        if (hhat > law.hhat_rupture) {  // ruptured: gone until the next contact
            s.bridged = false;
            return 0.0;
        }
        return law.force_scale * radius * gamma * bridge::mikami_fhat(law, hhat);
    }

    // Potential energy of this pair's bridge, J (≤ 0; 0 without a bridge).
    double stored_energy(const ContactPair& c, const State& s) const {
        if (!s.bridged || (c.wall && !wall)) return 0.0;
        return potential(c.wall ? *wall : k, c);
    }

private:
    double potential(const bridge::MikamiCoefficients& law, const ContactPair& c) const {
        return -law.force_scale * radius * radius * gamma * bridge::mikami_work_to_rupture(law, -c.overlap / radius);
    }
};

}  // namespace demscale::dem
