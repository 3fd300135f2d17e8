// Spheres stored as structure of arrays: one contiguous array per quantity, SI units.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

#include "core/memory_use.hpp"

namespace demscale::dem {

using Vec3 = Eigen::Vector3d;

// Keeps v's elements at order[0], order[1], … in that order: one per-sphere (or per-pair) array
// reordered or selected. Every such reorder of the engine goes through it.
template <class T, class A>
void gather(std::vector<T, A>& v, const std::vector<std::uint32_t>& order) {
    std::vector<T, A> kept(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) kept[k] = v[order[k]];
    v = std::move(kept);
}

// Loops over fewer items than this (particles, pairs) run on one thread: starting threads would
// cost more than the work.
inline constexpr long parallel_threshold = 512;

struct Particles {
    std::vector<Vec3> position;          // m
    std::vector<Vec3> velocity;          // m/s
    std::vector<Vec3> angular_velocity;  // rad/s
    std::vector<Vec3> force;             // N, rebuilt every step
    std::vector<Vec3> torque;            // N m, rebuilt every step
    std::vector<double> radius;          // m
    std::vector<double> mass;            // kg
    std::vector<double> inertia;         // kg m², solid sphere 2/5 m r²
    std::vector<int> species;
    std::vector<std::uint8_t> fixed;     // 1: held in place (a rough floor's grain), never moves

    std::size_t size() const { return radius.size(); }
    // What the arrays hold (their capacities), bytes.
    std::size_t bytes() const {
        return capacity_bytes(position) + capacity_bytes(velocity) + capacity_bytes(angular_velocity) + capacity_bytes(force) +
               capacity_bytes(torque) + capacity_bytes(radius) + capacity_bytes(mass) + capacity_bytes(inertia) + capacity_bytes(species) +
               capacity_bytes(fixed);
    }
    std::size_t mobile_count() const;

    // A solid sphere of density rho (kg/m³). Returns its index.
    std::size_t add(const Vec3& x, double r, double rho, const Vec3& v = Vec3::Zero(), int species_id = 0);
    // A sphere that pushes on the others and never moves (contacts with it see the mobile mass only).
    std::size_t add_fixed(const Vec3& x, double r, double rho, int species_id = 0);
    // Appends all of other's spheres (indices follow this set's).
    void append(const Particles& other);
    // A copy holding the mobile spheres only, in their order.
    Particles mobile() const;
    // Keeps the spheres at order[0], order[1], … in that order: a permutation reorders them, a
    // shorter list selects.
    void reorder(const std::vector<std::uint32_t>& order);

    // Every per-sphere array, for the operations above (one list: a new array cannot be forgotten).
    static constexpr auto arrays = std::tuple{&Particles::position, &Particles::velocity, &Particles::angular_velocity,
                                              &Particles::force,    &Particles::torque,   &Particles::radius,
                                              &Particles::mass,     &Particles::inertia,  &Particles::species,
                                              &Particles::fixed};
    template <class F>
    static void for_each_array(F f) {
        std::apply([&](auto... member) { (f(member), ...); }, arrays);
    }
};

// Momenta about the origin: Σ m v and Σ (x × m v + I ω).
inline Vec3 linear_momentum(const Particles& p) {
    Vec3 m = Vec3::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) m += p.mass[i] * p.velocity[i];
    return m;
}
inline Vec3 angular_momentum(const Particles& p) {
    Vec3 l = Vec3::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) l += p.position[i].cross(p.mass[i] * p.velocity[i]) + p.inertia[i] * p.angular_velocity[i];
    return l;
}

}  // namespace demscale::dem
