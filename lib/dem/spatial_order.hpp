// A cache-friendly order of the spheres: cell by cell through a grid of cubic cells, in rows along
// one axis, then the next, then layers along the slowest (as LAMMPS' `atom_modify sort` bins atoms),
// so that spheres near in space are near in memory and a pair's two spheres share cache lines. The
// engine reorders its spheres by it every so often (SpatialSort), with the scene's longest side as
// the slowest axis: the threads' slabs cut that side (pair_shares.hpp), so each thread's spheres
// then lie in one stretch of memory, which it alone writes through the step (with layers in z
// across slabs in x, each cache line of sphere state crossed between the cores about every step,
// docs/performance.md). In random order a packed bed of 3e5-1e6 spheres ran about 3x slower per
// sphere than in this one; a Z-order curve did a little worse than rows (performance.md, "Spatial
// sort").
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/particles.hpp"

namespace demscale::dem {

// When the engine reorders its spheres: once it holds at least min_particles, at its first
// neighbour-list build and then every `every_steps` steps (with a build forced then). Every scene
// whose pair loop runs on threads by default: a scene that fits the caches gains little on one
// thread, but threads that take slabs of space (pair_shares.hpp) write the forces of spheres near
// in memory only when these are near in space; in the order a pour left them, two threads wrote
// into the same cache lines and ran 1.2 times slower than with a shared buffer (docs/performance.md).
struct SpatialSort {
    std::size_t min_particles = 512;
    std::size_t every_steps = 1000;
};

// The spheres' indices ordered cell by cell (edge `cell`, m), the cells in layers along
// `slowest` (0 x, 1 y, 2 z), each layer in rows along the lower of the other two axes, row after
// row along the higher; ties (one cell) in index order: order[k] is the sphere to put k-th.
std::vector<std::uint32_t> spatial_order(const Particles& p, double cell, int slowest = 2);

// The axis of the longest side of the box around the spheres (the first of equal sides); 2 for none.
int longest_side(const Particles& p);

}  // namespace demscale::dem
