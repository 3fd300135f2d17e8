// The engine's contact geometry, as free functions of the particles: each pair's shape (R*, √R*,
// m*, computed once per neighbour list) and the ContactPair a law sees at one instant. SI units.
#pragma once

#include <cmath>
#include <cstddef>

#include "dem/contact_pair.hpp"
#include "dem/cross.hpp"
#include "dem/particles.hpp"

namespace demscale::dem {

struct PairShape {  // what a pair's radii and masses give
    double r_eff, sqrt_r_eff, m_eff, sqrt_m_eff;  // R* (m), √R* (m^½), m* (kg), √m* (kg^½)
    double rolling_compliance;                    // 1/I_r (rolling_compliance below), 1/(kg m²)
};

// The partner index of a particle–wall contact.
inline constexpr std::size_t a_wall = static_cast<std::size_t>(-1);

// 1/(I + m R²) of particle k, the inverse of its inertia about a contact point; 0 if fixed.
inline double rolling_compliance(const Particles& p, std::size_t k) {
    return p.fixed[k] ? 0.0 : 1.0 / (p.inertia[k] + p.mass[k] * p.radius[k] * p.radius[k]);
}

// R*, √R* and m* of particle i with j, or with a wall (j = a_wall: i's own radius and mass). m*
// is the mobile one's mass alone when the other is fixed (like a wall).
inline PairShape pair_shape(const Particles& p, std::size_t i, std::size_t j) {
    const double ri = p.radius[i], mi = p.mass[i];
    if (j == a_wall) return {ri, std::sqrt(ri), mi, std::sqrt(mi), rolling_compliance(p, i)};
    const double rj = p.radius[j], mj = p.mass[j], r_eff = ri * rj / (ri + rj);
    const double m_eff = p.fixed[i] ? mj : p.fixed[j] ? mi : mi * mj / (mi + mj);
    return {r_eff, std::sqrt(r_eff), m_eff, std::sqrt(m_eff), rolling_compliance(p, i) + rolling_compliance(p, j)};
}

// 2 R_i R_j / (R_i + R_j) of a pair of that shape: R_i itself for equal radii (bit for bit) and
// at a wall (rj = 0). Computed where used; a law that does not read it costs nothing.
inline double harmonic_radius(double ri, double rj, const PairShape& shape) { return rj == 0 || ri == rj ? ri : 2 * shape.r_eff; }

// Contact of particle i with partner j (or a_wall) moving with velocity vj and spin wj, radius rj
// (0 for a wall), at separation d = x_i − x_j, dist = |d| (the caller's range check already
// needed it), with the pair's shape, for a step dt (s).
template <class Law>
DEMSCALE_HOT ContactPair contact_geometry(const Law& law, const Particles& p, double dt, std::size_t i, const Vec3& d, double dist,
                                          const Vec3& vj, const Vec3& wj, double rj, const PairShape& shape, std::size_t j) {
    const bool wall = j == a_wall;
    ContactPair c;
    const double ri = p.radius[i];
    c.overlap = ri + rj - dist;
    c.normal = d * (1.0 / dist);  // one division, not three
    c.r_eff = shape.r_eff;
    c.sqrt_r_eff = shape.sqrt_r_eff;
    c.contact_radius = c.overlap > 0 ? c.sqrt_r_eff * std::sqrt(c.overlap) : 0.0;  // √R* √δ: one root per step
    c.m_eff = shape.m_eff;
    c.sqrt_m_eff = shape.sqrt_m_eff;
    c.r_harmonic = harmonic_radius(ri, rj, shape);
    c.dt = dt;
    c.wall = wall;
    if (c.overlap <= 0 && !law.needs_gap_velocity()) {  // apart: only cohesion acts, on the gap alone
        c.v_rel = c.v_tangential = c.w_rel = Vec3::Zero();
        return c;
    }
    // Contact point at the middle of the overlap (of the gap, for a viscous bridge); lever arms
    // from each centre.
    const double li = ri - 0.5 * c.overlap, lj = rj - 0.5 * c.overlap;
    c.v_rel = p.velocity[i] + cross(p.angular_velocity[i], -li * c.normal) - (vj + cross(wj, lj * c.normal));
    c.v_normal = c.v_rel.dot(c.normal);
    c.v_tangential = c.v_rel - c.v_normal * c.normal;
    c.w_rel = p.angular_velocity[i] - wj;
    if (law.rolling_damping() > 0) c.rolling_compliance = shape.rolling_compliance;
    return c;
}

}  // namespace demscale::dem
