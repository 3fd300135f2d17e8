// A contact law composed from one normal law and optional tangential, cohesion and rolling laws,
// fixed at compile time: ContactLaw<NormalHertz, TangentialMindlin, CohesionMikamiBridge, RollingEpsd>.
// An "off" part (TangentialNone, CohesionNone, RollingNone) has no state and compiles to nothing in
// the force loop, so a dry scene pays nothing for liquid bridges. Call order: normal → cohesion →
// tangential → rolling.
#pragma once

#include <utility>

#include "dem/contact_pair.hpp"
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
    double damping_power = 0;       // F_damping · v_rel (≤ 0), W
};

template <class Normal, class Tangential = TangentialNone, class Cohesion = CohesionNone, class Rolling = RollingNone>
struct ContactLaw {
    Normal normal;
    Tangential tangential;
    Cohesion cohesion;
    Rolling rolling;

    explicit ContactLaw(const Material& m, Cohesion c = {})
        : normal(m), tangential(m), cohesion(std::move(c)), rolling(m) {}

    struct State {
        [[no_unique_address]] typename Tangential::State tangential;
        [[no_unique_address]] typename Cohesion::State cohesion;
        [[no_unique_address]] typename Rolling::State rolling;
    };

    // Interaction range beyond touching surfaces, m (0 for dry laws).
    double range() const { return cohesion.range(); }

    ContactForce force(const ContactPair& c, State& s) const {
        ContactForce out;
        double fn = 0, elastic = 0;
        if (c.overlap > 0) {
            const double damping = normal.damping_force(c);
            elastic = normal.elastic_force(c);
            fn = elastic + damping;
            out.damping_power = damping * c.v_normal;
        }
        const double attraction = cohesion.force(c, s.cohesion);
        out.on_i = (fn - attraction) * c.normal;
        if (c.overlap > 0) {
            out.tangential = tangential.force(c, fn, s.tangential);
            out.on_i += out.tangential;
            // Rolling stiffness uses the secant normal stiffness F_el/δ (as LIGGGHTS' epsd2 does).
            out.rolling_torque = rolling.torque(c, elastic / c.overlap, fn, s.rolling);
        } else {  // surfaces apart: tangential and rolling springs are released
            s.tangential = {};
            s.rolling = {};
        }
        return out;
    }

    double elastic_energy(const ContactPair& c) const { return c.overlap > 0 ? normal.elastic_energy(c) : 0.0; }
};

}  // namespace demscale::dem
