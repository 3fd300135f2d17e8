// Hertz (1882) normal contact with viscous damping from the coefficient of restitution:
//   F_el = 4/3 E* √R* δ^(3/2),  S_n = 2 E* √(R* δ),
//   F_d  = −2 √(5/6) β √(S_n m*) v_n,  β = ln e / √(ln² e + π²)
// (Tsuji, Tanaka & Ishida 1992 damping in the form used by EDEM and LIGGGHTS' hertz model). SI units.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct NormalHertz {
    double e_star;  // Pa
    double beta;    // damping ratio (≤ 0)

    explicit NormalHertz(const Material& m) : e_star(effective_youngs(m)), beta(damping_ratio(m.restitution)) {}

    // Tangent normal stiffness S_n = dF_el/dδ, which scales the damping.
    double stiffness(const ContactPair& c) const { return 2.0 * e_star * c.contact_radius; }
    double elastic_force(const ContactPair& c) const {
        return 4.0 / 3.0 * e_star * c.sqrt_r_eff * c.overlap * std::sqrt(c.overlap);
    }
    double damping_force(const ContactPair& c) const {
        return 2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(stiffness(c) * c.m_eff) * c.v_normal;
    }
    // Stored energy 8/15 E* √R* δ^(5/2).
    double elastic_energy(const ContactPair& c) const {
        return 8.0 / 15.0 * e_star * c.sqrt_r_eff * std::pow(c.overlap, 2.5);
    }
};

}  // namespace demscale::dem
