// The energy ledger of a DEM run, J. What the contacts store (a state function of the current
// contacts), what they have dissipated so far (each law books its own loss as it happens), and the
// work moving walls did on the particles. Conserved: kinetic + gravitational + stored + dissipated
// − wall work, up to the integrator's error (first order in dt: the dashpots are booked with the
// mid-step velocity).
#pragma once

#include <type_traits>

namespace demscale::dem {

// Energy lost by each mechanism, J.
struct Dissipation {
    double normal_damping = 0;  // normal dashpot (≥ 0)
    double friction = 0;        // tangential dashpot and Coulomb sliding (≥ 0)
    double rolling = 0;         // plastic rolling: the rolling spring at its limit (≥ 0)
    double bridge = 0;          // bridge formation: a bridge appears at contact with negative potential (≥ 0)
    // The incremental tangential and rolling springs are not conservative: their stiffness follows
    // the overlap with no work paid (a negative loss while it grows), and they still hold a little
    // when the surfaces part. About 4 % of the total in a collapsing pile; either sign.
    double spring_stiffness = 0;
    double total() const { return normal_damping + friction + rolling + bridge + spring_stiffness; }
    Dissipation& operator+=(const Dissipation& o) {
        normal_damping += o.normal_damping, friction += o.friction, rolling += o.rolling, bridge += o.bridge;
        spring_stiffness += o.spring_stiffness;
        return *this;
    }
};

// The ledger of an engine built without one: every booking compiles to nothing, so a run that
// does not ask for energies pays nothing for them (Simulation<Law, false>).
struct Discard {
    constexpr Discard& operator+=(double) { return *this; }
    constexpr Discard& operator-=(double) { return *this; }
};
struct NoDissipation {
    [[no_unique_address]] Discard normal_damping, friction, rolling, bridge, spring_stiffness;
    constexpr NoDissipation& operator+=(const NoDissipation&) { return *this; }
};

// Whether a law books its losses (Dissipation) or an engine without a ledger runs it (NoDissipation).
template <class Lost>
inline constexpr bool books_losses = !std::is_same_v<Lost, NoDissipation>;

// A history spring's stiffness at the last step, N/m or N m/rad: the ledger books its change. An
// engine without the ledger keeps none, so each pair's state is 8 bytes shorter per spring (the
// pair loop reads less memory).
template <class Lost>
struct LastStiffness {
    double value = 0;
};
template <>
struct LastStiffness<NoDissipation> {};

// Energy held by the contacts now, J.
struct StoredEnergy {
    double normal = 0;      // normal springs (Hertz: 8/15 E* √R* δ^(5/2))
    double tangential = 0;  // tangential springs, ½ S_t |ξ|²
    double rolling = 0;     // rolling springs, ½ |M|² / k_r
    double bridge = 0;      // liquid bridges, −(work to pull each to rupture) ≤ 0
    double total() const { return normal + tangential + rolling + bridge; }
    StoredEnergy& operator+=(const StoredEnergy& o) {
        normal += o.normal, tangential += o.tangential, rolling += o.rolling, bridge += o.bridge;
        return *this;
    }
};

struct Energy {
    double kinetic = 0;        // translational + rotational
    double gravitational = 0;  // Σ −m g·x (zero at the origin)
    StoredEnergy stored;
    Dissipation dissipated;    // so far
    double wall_work = 0;      // done by walls on particles so far (a moving wall can add energy)
    // Constant in time for an exact integrator.
    double balance() const { return kinetic + gravitational + stored.total() + dissipated.total() - wall_work; }
};

}  // namespace demscale::dem
