// The engine's cost as the work grows (bench --dem --sizes): the scene's cone and fill scaled in
// every length (R kept) until the lattice fill holds about the asked number of spheres, packed to
// touching (pitch 2R: up to 12 contacts each, denser than a pile's 5-7), then stepped from rest
// with the cone in place. Every size runs the same steps (the same motion: a bed stepped longer
// loosens as the cone rises, and a looser bed has fewer contacts to compute). The per-step rate
// comes from pairs of runs of S and 3S steps after a warm-up run (their difference: set-up
// excluded), repeated at small sizes until enough work is timed; the work per particle is the
// contacts each carries at the end of the last run (deeper beds press more spheres together), and
// the rate per contact divides it out. Memory is the peak resident size of the longer run over
// what was resident before it, per particle.
#pragma once

#include <cstddef>

#include "core/memory_use.hpp"
#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct SizePoint {
    std::size_t particles = 0;
    std::size_t steps = 0;             // the steps timed: the longer runs' less the shorter's
    double wall_s = 0;                 // their wall time: ≤ 0 when the set-up's noise exceeded it
    double particle_steps_per_s = 0;   // 0 when not timed (wall_s ≤ 0): more steps are needed
    double contacts_per_particle = 0;  // sphere-sphere contacts (overlapping pairs) per sphere, at the end
    double contact_steps_per_s = 0;    // contacts × steps / s: the rate per unit of contact work
    double peak_bytes_per_particle = 0;  // 0: the kernel does not say
    std::vector<MemoryItem> engine_memory;  // the engine's own, by consumer, at the end of the last run (bytes)
};

// The scene with its cone, lift height, fill height and rough floor scaled by `factor`.
SlumpScene scaled_cone(const SlumpScene& scene, double factor);

// The scene's lattice fill (pitch 2.02 R) drawn together to pitch 2 R about the axis and the
// lowest centre: neighbours touch. shuffled: see time_size.
dem::Particles packed_fill(const SlumpScene& scene, bool shuffled);

// Overlapping sphere pairs (δ > 0; never two fixed spheres) per sphere: the contacts a step
// computes, counted from positions alone (a liquid bridge across a gap is not counted).
double contacts_per_particle(const dem::Particles& p);

// shuffled: the particles' order randomly permuted (seeded), as after much mixing, instead of
// the lattice's own order (neighbours near in memory). timed_work: particle-steps to time at
// least (pairs of runs are repeated until their timed steps reach it; at least one pair).
SizePoint time_size(const SlumpScene& scene, double particles, int steps, bool shuffled, double timed_work);

}  // namespace demscale::slump
