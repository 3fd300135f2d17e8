// Verlet neighbour list built with a cell list. A pair is listed when its surfaces are closer than
// the skin: only touching starts an interaction, and the engine keeps the pairs a liquid bridge
// holds on its own (Simulation::rebuild), so no bridge is missed. Rebuilt when the two particles
// that moved most since the last build have moved more than the skin between them.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

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
