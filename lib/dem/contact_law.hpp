// A contact law composed from one normal law and optional tangential and cohesion laws, fixed at
// compile time: ContactLaw<NormalHertz, TangentialMindlin, CohesionMikamiBridge>. An "off" part
// (TangentialNone, CohesionNone) has no state and compiles to nothing in the force loop, so a dry
// scene pays nothing for liquid bridges. Call order: normal → cohesion → tangential.
#pragma once

#include <utility>

#include "dem/contact_pair.hpp"
#include "dem/laws/cohesion.hpp"
#include "dem/laws/normal_hertz.hpp"
#include "dem/laws/normal_linear.hpp"
#include "dem/laws/tangential.hpp"

namespace demscale::dem {

struct ContactForce {
    Vec3 on_i = Vec3::Zero();       // force on particle i (j gets −on_i)
    Vec3 tangential = Vec3::Zero(); // its tangential part (for torques)
    double damping_power = 0;       // F_damping · v_rel (≤ 0), W
};

template <class Normal, class Tangential = TangentialNone, class Cohesion = CohesionNone>
struct ContactLaw {
    Normal normal;
    Tangential tangential;
    Cohesion cohesion;

    explicit ContactLaw(const Material& m, Cohesion c = {}) : normal(m), tangential(m), cohesion(std::move(c)) {}

    struct State {
        [[no_unique_address]] typename Tangential::State tangential;
        [[no_unique_address]] typename Cohesion::State cohesion;
    };

    // Interaction range beyond touching surfaces, m (0 for dry laws).
    double range() const { return cohesion.range(); }

    ContactForce force(const ContactPair& c, State& s) const {
        ContactForce out;
        double fn = 0;
        if (c.overlap > 0) {
            const double damping = normal.damping_force(c);
            fn = normal.elastic_force(c) + damping;
            out.damping_power = damping * c.v_normal;
        }
        const double attraction = cohesion.force(c, s.cohesion);
        out.on_i = (fn - attraction) * c.normal;
        if (c.overlap > 0) {
            out.tangential = tangential.force(c, fn, s.tangential);
            out.on_i += out.tangential;
        } else {
            s.tangential = {};  // surfaces apart: the tangential spring is released
        }
        return out;
    }

    double elastic_energy(const ContactPair& c) const { return c.overlap > 0 ? normal.elastic_energy(c) : 0.0; }
};

}  // namespace demscale::dem
