// A cache-friendly order of the spheres: cell by cell through a grid of cubic cells, rows along x,
// then y, then layers in z (as LAMMPS' `atom_modify sort` bins atoms), so that spheres near in
// space are near in memory and a pair's two spheres share cache lines. The engine reorders its
// spheres by it every so often (SpatialSort). In random order a packed bed of 3e5-1e6 spheres ran
// about 3x slower per sphere than in this one; a Z-order curve did a little worse than rows
// (performance.md, "Spatial sort").
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/particles.hpp"

namespace demscale::dem {

// When the engine reorders its spheres: once it holds at least min_particles, at its first
// neighbour-list build and then at the first build after every `every_steps` steps. Below
// min_particles (about what the caches hold) the spheres keep the order they were given.
struct SpatialSort {
    std::size_t min_particles = 16384;
    std::size_t every_steps = 1000;
};

// The spheres' indices ordered cell by cell (edge `cell`, m; rows along x, then y, then z), ties
// (one cell) in index order: order[k] is the sphere to put k-th.
std::vector<std::uint32_t> spatial_order(const Particles& p, double cell);

}  // namespace demscale::dem
