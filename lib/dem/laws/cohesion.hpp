// Cohesion laws.
//  CohesionNone — dry: zero range, no state, no code in the force loop.
//  CohesionMikamiBridge — static pendular liquid bridge (Mikami et al. 1998 via the bridge library):
//    a bridge forms when two surfaces touch, pulls with F = force_scale·R·γ·F̂(ĥ) (ĥ = gap/R) while
//    the gap stays below the rupture distance ĥ_c·R, and is gone until the surfaces touch again.
//    Equal spheres of radius R (monodisperse wet scenes); coefficients computed once (one exp per force).
#pragma once

#include "bridge/mikami.hpp"
#include "dem/contact_pair.hpp"

namespace demscale::dem {

struct CohesionNone {
    struct State {};
    double range() const { return 0.0; }
    double force(const ContactPair&, State&) const { return 0.0; }
};

struct CohesionMikamiBridge {
    struct State {
        bool bridged = false;
    };
    bridge::MikamiCoefficients k;
    double radius;         // R of the equal spheres, m
    double gamma;          // surface tension, N/m

    // Range beyond contact the neighbour search must cover: the rupture gap, m.
    double range() const { return k.hhat_rupture * radius; }

    // Attractive force magnitude (N) along −n on particle i.
    double force(const ContactPair& c, State& s) const {
        if (c.overlap >= 0) s.bridged = true;  // forms at contact
        if (!s.bridged) return 0.0;
        const double hhat = -c.overlap / radius;
        if (hhat > k.hhat_rupture) {  // ruptured: gone until the next contact
            s.bridged = false;
            return 0.0;
        }
        return k.force_scale * radius * gamma * bridge::mikami_fhat(k, hhat);
    }
};

}  // namespace demscale::dem
