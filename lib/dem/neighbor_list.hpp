// Verlet neighbour list built with a cell list. A pair is listed when its surfaces are closer than
// the skin: only touching starts an interaction, and the engine keeps the pairs a liquid bridge
// holds on its own (Simulation::rebuild), so no bridge is missed. Rebuilt when the two particles
// that moved most since the last build have moved more than the skin between them.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/memory_use.hpp"
#include "dem/particles.hpp"

namespace demscale::dem {

class NeighborList {
public:
    explicit NeighborList(double skin) : skin_(skin) {}

    // Pairs (i, j) in ascending order of (i, j), never two fixed spheres, each oriented by rank:
    // rank[i] < rank[j] (the engine's spheres' input order, kept by a pair whatever its spheres'
    // places in memory); without ranks, i < j.
    void build(const Particles& p, const std::vector<std::uint32_t>* rank = nullptr);
    bool needs_rebuild(const Particles& p) const;

    // The two largest squared shifts of some spheres since the build, m² (any order of keeping
    // and merging gives the same two): the engine gathers them in its pass over the spheres.
    struct Shifts {
        double top = 0, next = 0;
        void keep(double shift) {
            if (shift > top) next = top, top = shift;
            else if (shift > next) next = shift;
        }
        Shifts& operator+=(const Shifts& other) { return keep(other.top), keep(other.next), *this; }
    };
    // Sphere i's squared shift since the build (built for these spheres: built_for(p)).
    double squared_shift(const Particles& p, std::size_t i) const { return (p.position[i] - built_at_[i]).squaredNorm(); }
    bool built_for(const Particles& p) const { return built_at_.size() == p.size(); }
    // Whether the spheres whose shifts these are, all of them, call for a rebuild.
    bool needs_rebuild(const Shifts& all) const;
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs() const { return pairs_; }
    std::size_t builds() const { return builds_; }

    // Checkpoint support: the positions at the last build decide the next rebuild.
    const std::vector<Vec3>& built_at() const { return built_at_; }
    void restore(std::vector<Vec3> built_at, std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs, std::size_t builds) {
        built_at_ = std::move(built_at);
        pairs_ = std::move(pairs);
        builds_ = builds;
    }
    double cutoff_gap() const { return skin_; }
    // The list's pairs and the positions at its build, bytes.
    std::size_t bytes() const { return capacity_bytes(pairs_) + capacity_bytes(built_at_); }

private:
    double skin_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
    std::vector<Vec3> built_at_;
    std::size_t builds_ = 0;
};

// All pairs whose surface gap is below `gap` (but no two fixed spheres), by checking every pair:
// the reference for tests.
std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const Particles& p, double gap);

}  // namespace demscale::dem
