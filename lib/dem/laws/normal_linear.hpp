// Linear spring–dashpot normal contact: F = k δ − c v_n with c = −2β √(k m*), β from the
// restitution (Tsuji et al. 1992), which gives exactly e for an isolated collision. SI units.
#pragma once

#include <cmath>

#include "dem/contact_pair.hpp"
#include "dem/material.hpp"

namespace demscale::dem {

struct NormalLinear {
    double k;     // N/m
    double beta;  // ≤ 0

    explicit NormalLinear(const Material& m) : k(m.linear_stiffness), beta(damping_ratio(m.restitution)) {}

    double elastic_force(const ContactPair& c) const { return k * c.overlap; }
    double secant_stiffness(const ContactPair&) const { return k; }  // F_el / δ, N/m
    double damping_force(const ContactPair& c) const { return 2.0 * beta * std::sqrt(k * c.m_eff) * c.v_normal; }
    double elastic_energy(const ContactPair& c) const { return 0.5 * k * c.overlap * c.overlap; }
};

}  // namespace demscale::dem
