// The DEM engine for one contact law: particles, plane walls, gravity, velocity-Verlet integration
// (translation and rotation), a Verlet neighbour list with contact history carried across rebuilds,
// and energy bookkeeping. SI units. Serial for now; the force loop is written pair by pair so it can
// be split across threads later.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/input_error.hpp"
#include "dem/contact_law.hpp"
#include "dem/neighbor_list.hpp"
#include "dem/walls.hpp"

namespace demscale::dem {

struct Energy {
    double kinetic = 0;        // translational + rotational, J
    double gravitational = 0;  // Σ −m g·x, J (zero at the origin)
    double elastic = 0;        // normal springs in contact, J
    double damped = 0;         // dissipated by normal damping so far, J
};

template <class Law>
class Simulation {
public:
    Simulation(Particles particles, Law law, std::vector<Wall> walls, Vec3 gravity, double dt, double skin)
        : p_(std::move(particles)), law_(std::move(law)), walls_(std::move(walls)), gravity_(gravity), dt_(dt),
          neighbors_(law_.range(), skin) {
        require_positive(dt, "dt");
        require_positive(skin, "skin");
        wall_state_.assign(walls_.size(), std::vector<typename Law::State>(p_.size()));
        rebuild();
        compute_forces();
    }

    // One velocity-Verlet step: half kick, drift, forces, half kick.
    void step() {
        half_kick();
        for (std::size_t i = 0; i < p_.size(); ++i) p_.position[i] += dt_ * p_.velocity[i];
        if (neighbors_.needs_rebuild(p_)) rebuild();
        compute_forces();
        half_kick();
        time_ += dt_;
        ++steps_;
    }

    const Particles& particles() const { return p_; }
    Particles& particles() { return p_; }

    // Forces for the current state after particles were moved by hand (tests, prescribed motion).
    void refresh_forces() {
        if (neighbors_.needs_rebuild(p_)) rebuild();
        compute_forces();
    }
    const NeighborList& neighbors() const { return neighbors_; }
    double time() const { return time_; }
    std::size_t steps() const { return steps_; }
    double dt() const { return dt_; }

    Energy energy() const {
        Energy e = energy_;
        e.kinetic = e.gravitational = 0;
        for (std::size_t i = 0; i < p_.size(); ++i) {
            e.kinetic += 0.5 * p_.mass[i] * p_.velocity[i].squaredNorm() +
                         0.5 * p_.inertia[i] * p_.angular_velocity[i].squaredNorm();
            e.gravitational -= p_.mass[i] * gravity_.dot(p_.position[i]);
        }
        return e;
    }

    // Momenta about the origin: Σ m v and Σ (x × m v + I ω).
    Vec3 linear_momentum() const {
        Vec3 m = Vec3::Zero();
        for (std::size_t i = 0; i < p_.size(); ++i) m += p_.mass[i] * p_.velocity[i];
        return m;
    }
    Vec3 angular_momentum() const {
        Vec3 l = Vec3::Zero();
        for (std::size_t i = 0; i < p_.size(); ++i)
            l += p_.position[i].cross(p_.mass[i] * p_.velocity[i]) + p_.inertia[i] * p_.angular_velocity[i];
        return l;
    }

private:
    struct ListedPair {
        std::uint32_t i, j;
        typename Law::State state;
    };

    void half_kick() {
        for (std::size_t i = 0; i < p_.size(); ++i) {
            p_.velocity[i] += 0.5 * dt_ / p_.mass[i] * p_.force[i];
            p_.angular_velocity[i] += 0.5 * dt_ / p_.inertia[i] * p_.torque[i];
        }
    }

    // New pair list; contact history moves with the pairs that are still listed.
    void rebuild() {
        std::unordered_map<std::uint64_t, typename Law::State> old;
        old.reserve(pairs_.size());
        for (const auto& q : pairs_) old.emplace((std::uint64_t(q.i) << 32) | q.j, q.state);
        neighbors_.build(p_);
        pairs_.clear();
        for (const auto& [i, j] : neighbors_.pairs()) {
            auto it = old.find((std::uint64_t(i) << 32) | j);
            pairs_.push_back({i, j, it == old.end() ? typename Law::State{} : it->second});
        }
    }

    ContactPair pair_geometry(std::size_t i, const Vec3& xj, const Vec3& vj, const Vec3& wj, double rj, double mj,
                              bool wall) const {
        ContactPair c;
        const Vec3 d = p_.position[i] - xj;
        const double dist = d.norm();
        const double ri = p_.radius[i];
        c.overlap = ri + rj - dist;
        c.normal = d / dist;
        c.r_eff = wall ? ri : ri * rj / (ri + rj);
        c.m_eff = wall ? p_.mass[i] : p_.mass[i] * mj / (p_.mass[i] + mj);
        // Contact point at the middle of the overlap; lever arms from each centre.
        const double li = ri - 0.5 * c.overlap, lj = rj - 0.5 * c.overlap;
        c.v_rel = p_.velocity[i] + p_.angular_velocity[i].cross(-li * c.normal) - (vj + wj.cross(lj * c.normal));
        c.v_normal = c.v_rel.dot(c.normal);
        c.v_tangential = c.v_rel - c.v_normal * c.normal;
        c.w_rel = p_.angular_velocity[i] - wj;
        c.dt = dt_;
        return c;
    }

    void compute_forces() {
        double elastic = 0, damping_power = 0;
        for (std::size_t i = 0; i < p_.size(); ++i) {
            p_.force[i] = p_.mass[i] * gravity_;
            p_.torque[i].setZero();
        }
        const double reach = law_.range();
        for (auto& q : pairs_) {
            const std::size_t i = q.i, j = q.j;
            const double gap = (p_.position[i] - p_.position[j]).norm() - p_.radius[i] - p_.radius[j];
            if (gap > reach) {
                q.state = {};
                continue;
            }
            const ContactPair c = pair_geometry(i, p_.position[j], p_.velocity[j], p_.angular_velocity[j], p_.radius[j],
                                                p_.mass[j], false);
            const ContactForce f = law_.force(c, q.state);
            p_.force[i] += f.on_i;
            p_.force[j] -= f.on_i;
            const double li = p_.radius[i] - 0.5 * c.overlap, lj = p_.radius[j] - 0.5 * c.overlap;
            p_.torque[i] += (-li * c.normal).cross(f.tangential) + f.rolling_torque;
            p_.torque[j] += (lj * c.normal).cross(-f.tangential) - f.rolling_torque;
            elastic += law_.elastic_energy(c);
            damping_power += f.damping_power;
        }
        for (std::size_t w = 0; w < walls_.size(); ++w) {
            for (std::size_t i = 0; i < p_.size(); ++i) {
                const WallPoint wp = closest_wall_point(walls_[w], p_.position[i], time_);
                if (wp.behind)
                    throw std::runtime_error("particle " + std::to_string(i) + " left the domain through wall " +
                                             std::to_string(w) + " at step " + std::to_string(steps_));
                if ((p_.position[i] - wp.point).norm() - p_.radius[i] > reach) {
                    wall_state_[w][i] = {};
                    continue;
                }
                const ContactPair c = pair_geometry(i, wp.point, wp.velocity, Vec3::Zero(), 0.0, 0.0, true);
                const ContactForce f = law_.force(c, wall_state_[w][i]);
                p_.force[i] += f.on_i;
                p_.torque[i] += (-(p_.radius[i] - 0.5 * c.overlap) * c.normal).cross(f.tangential) + f.rolling_torque;
                elastic += law_.elastic_energy(c);
                damping_power += f.damping_power;
            }
        }
        for (std::size_t i = 0; i < p_.size(); ++i)
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(p_.force[i][k]))
                    throw std::runtime_error("non-finite force on particle " + std::to_string(i) + " at step " +
                                             std::to_string(steps_));
        energy_.elastic = elastic;
        energy_.damped -= damping_power * dt_;
    }

    Particles p_;
    Law law_;
    std::vector<Wall> walls_;
    Vec3 gravity_;
    double dt_;
    NeighborList neighbors_;
    std::vector<ListedPair> pairs_;
    std::vector<std::vector<typename Law::State>> wall_state_;
    Energy energy_;
    double time_ = 0;
    std::size_t steps_ = 0;
};

}  // namespace demscale::dem
