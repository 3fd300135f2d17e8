// A contact law composed from one normal law and optional tangential, cohesion and rolling laws,
// fixed at compile time: ContactLaw<NormalHertz, TangentialMindlin, CohesionLiquidBridge, RollingEpsd>.
// An "off" part (TangentialNone, CohesionNone, RollingNone) has no state and compiles to nothing in
// the force loop, so a dry scene pays nothing for liquid bridges. Call order: normal → cohesion →
// tangential → rolling.
#pragma once

#include <utility>

#include "dem/contact_pair.hpp"
#include "dem/energy.hpp"
#include "dem/laws/cohesion.hpp"
#include "dem/laws/normal_hertz.hpp"
#include "dem/laws/normal_linear.hpp"
#include "dem/laws/rolling.hpp"
#include "dem/laws/tangential.hpp"

namespace demscale::dem {

struct ContactForce {
    Vec3 on_i = Vec3::Zero();       // force on particle i (j gets −on_i)
    Vec3 tangential = Vec3::Zero(); // its tangential part (for torques)
    Vec3 rolling_torque = Vec3::Zero();  // on i (j gets the opposite)
};

template <class Normal, class Tangential = TangentialNone, class Cohesion = CohesionNone, class Rolling = RollingNone>
struct ContactLaw {
    Normal normal;
    Tangential tangential;
    Cohesion cohesion;
    Rolling rolling;

    explicit ContactLaw(const Material& m, Cohesion c = {})
        : normal(m), tangential(m), cohesion(std::move(c)), rolling(m) {}
    // With a rolling law built apart (RollingChosen takes the scene's choice).
    ContactLaw(const Material& m, Cohesion c, Rolling r)
        : normal(m), tangential(m), cohesion(std::move(c)), rolling(std::move(r)) {}

    // A pair's contact history. Lost = Dissipation: as the ledger needs it; NoDissipation: without
    // the springs' last stiffnesses (16 bytes less per pair with both springs).
    template <class Lost>
    struct StateFor {
        [[no_unique_address]] typename Tangential::template StateFor<Lost> tangential;
        [[no_unique_address]] typename Cohesion::template StateFor<Lost> cohesion;
        [[no_unique_address]] typename Rolling::template StateFor<Lost> rolling;
    };
    using State = StateFor<Dissipation>;

    // Interaction range beyond touching surfaces, m (0 for dry laws).
    double range() const { return cohesion.range(); }

    // Whether anything acts on a pair whose surfaces are apart (a liquid bridge holds it).
    template <class Lost>
    bool acts_across_gap(const StateFor<Lost>& s) const { return cohesion.holds(s.cohesion); }

    // η_r of the rolling dashpot (0 when the rolling law has none): the engine then sets the
    // pair's rolling compliance.
    double rolling_damping() const {
        if constexpr (requires { rolling.eta_r; }) return rolling.eta_r;
        else return 0.0;
    }

    // lost: what this step dissipates is added (Dissipation), or nothing is booked (NoDissipation).
    template <class Lost>
    DEMSCALE_HOT ContactForce force(const ContactPair& c, StateFor<Lost>& s, Lost& lost) const {
        ContactForce out;
        if (c.overlap <= 0) {  // surfaces apart: a bridge's pull (and drag) at most, the springs released
            out.on_i = (0.0 - pull_apart(c.overlap, c.r_harmonic, c.v_normal, c.dt, c.wall, s, lost)) * c.normal;
            if (needs_gap_velocity()) {
                out.tangential = cohesion.drag(c.overlap, c.r_harmonic, c.v_tangential, c.dt, c.wall, s.cohesion, lost);
                out.on_i += out.tangential;
            }
            return out;
        }
        const double damping = normal.damping_force(c);
        const double elastic = normal.elastic_force(c), fn = elastic + damping;
        lost.normal_damping += -damping * c.v_normal * c.dt;
        const double attraction = cohesion.pull(c.overlap, c.r_harmonic, c.v_normal, c.dt, c.wall, s.cohesion, lost);
        out.on_i = (fn - attraction) * c.normal;
        out.tangential = tangential.force(c, fn, s.tangential, lost);
        if (needs_gap_velocity()) out.tangential += cohesion.drag(c.overlap, c.r_harmonic, c.v_tangential, c.dt, c.wall, s.cohesion, lost);
        out.on_i += out.tangential;
        // Rolling laws get the secant normal stiffness F_el/δ (as LIGGGHTS' kn) and the tangential one.
        out.rolling_torque = rolling.torque(c, normal.secant_stiffness(c), tangential.stiffness(c), fn, s.rolling, lost);
        return out;
    }

    // Whether a pair across a gap needs its velocities (a viscous bridge: normal and tangential
    // lubrication): otherwise the engine leaves them 0, computes no velocity there, and a bridge
    // across a gap pulls along the line of centres only.
    bool needs_gap_velocity() const { return cohesion.needs_gap_velocity(); }

    // force() for surfaces apart (overlap δ ≤ 0, m), where only a bridge can act: its attraction
    // (N, along −n on i), the springs released. It needs no masses and, unless needs_gap_velocity(),
    // no velocity (v_normal, m/s, > 0 separating), so the engine calls it directly for a bridged
    // pair across a gap. r_harmonic: the pair's ContactPair::r_harmonic, m; dt: s, for the ledger.
    template <class Lost>
    DEMSCALE_HOT double pull_apart(double overlap, double r_harmonic, double v_normal, double dt, bool with_wall, StateFor<Lost>& s,
                                   Lost& lost) const {
        const double attraction = cohesion.pull(overlap, r_harmonic, v_normal, dt, with_wall, s.cohesion, lost);
        tangential.release(s.tangential, lost);
        rolling.release(s.rolling, lost);
        return attraction;
    }

    // The pair moved out of range: forget its history, booking what its springs still held.
    template <class Lost>
    void release(StateFor<Lost>& s, Lost& lost) const {
        tangential.release(s.tangential, lost);
        rolling.release(s.rolling, lost);
        s = {};
    }

    // What this contact holds now (its state as the last force evaluation left it), J.
    template <class Lost>
    StoredEnergy stored_energy(const ContactPair& c, const StateFor<Lost>& s) const {
        StoredEnergy e;
        e.bridge = cohesion.stored_energy(c, s.cohesion);
        if (c.overlap > 0) {
            e.normal = normal.elastic_energy(c);
            e.tangential = tangential.stored_energy(c, s.tangential);
            e.rolling = rolling.stored_energy(c, normal.secant_stiffness(c), tangential.stiffness(c), s.rolling);
        }
        return e;
    }
};

}  // namespace demscale::dem
