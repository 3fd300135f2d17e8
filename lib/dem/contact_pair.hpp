// What every contact law needs to know about one pair at one instant: effective radius and mass,
// overlap, unit normal and relative velocity at the contact point. Particle–wall pairs use the
// particle's own radius and mass (the wall is infinitely large and heavy). Apart (δ ≤ 0) only the
// cohesion law acts, on the gap alone: the velocities are left zero. SI units.
#pragma once

#include "dem/particles.hpp"

// For the few functions of the pair loop that GCC leaves out of line: called once per pair per step.
#define DEMSCALE_HOT [[gnu::always_inline]] inline

namespace demscale::dem {

struct ContactPair {
    double r_eff = 0;      // R* = R_i R_j / (R_i + R_j)   (wall: R_i)
    double sqrt_r_eff = 0; // √R*, m^½ (Hertz; computed once per pair, not per step)
    double m_eff = 0;      // m* = m_i m_j / (m_i + m_j)   (wall: m_i)
    double sqrt_m_eff = 0; // √m*, kg^½ (the dashpots; computed once per pair)
    double r_harmonic = 0; // 2 R_i R_j / (R_i + R_j), exactly R_i when the radii are equal (wall: R_i);
                           // the R of a liquid bridge between unequal spheres (Mikami et al. 1998)
    double overlap = 0;    // δ = R_i + R_j − |x_i − x_j|  (> 0 in contact, < 0 a gap)
    double contact_radius = 0;  // a = √(R* δ) in contact, else 0: Hertz and Mindlin stiffness share it
    Vec3 normal;           // unit vector from j to i
    Vec3 v_rel;            // velocity of i relative to j at the contact point
    double v_normal = 0;   // v_rel · n (< 0 approaching)
    Vec3 v_tangential;     // v_rel − v_normal n
    Vec3 w_rel;            // ω_i − ω_j (rolling)
    double rolling_compliance = 0;  // 1/I_r = 1/(I_i + m_i R_i²) + 1/(I_j + m_j R_j²), 1/(kg m²), Ai et al.
                                    // (2011); a wall or fixed sphere adds 0. Set only for a rolling dashpot.
    double dt = 0;         // time step, for history updates
    bool wall = false;     // j is a wall
};

}  // namespace demscale::dem
