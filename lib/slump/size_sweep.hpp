// The engine's cost as the work grows (bench --dem --sizes): the scene's cone and fill scaled in
// every length (R kept) until the lattice fill holds about the asked number of spheres, packed to
// touching (pitch 2R: up to 12 contacts each, denser than a pile's 5-7), then stepped from rest
// with the cone in place. The per-step rate comes from two runs of S and 3S steps after a warm-up
// run (their difference: set-up excluded); memory is the peak resident size of the longer run over what was
// resident before it, per particle.
#pragma once

#include <cstddef>

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct SizePoint {
    std::size_t particles = 0;
    std::size_t steps = 0;             // the steps timed: the longer run's less the shorter's
    double wall_s = 0;                 // their wall time: ≤ 0 when the set-up's noise exceeded it
    double particle_steps_per_s = 0;   // 0 when not timed (wall_s ≤ 0): more steps are needed
    double peak_bytes_per_particle = 0;  // 0: the kernel does not say
};

// The scene with its cone, lift height, fill height and rough floor scaled by `factor`.
SlumpScene scaled_cone(const SlumpScene& scene, double factor);

// The scene's lattice fill (pitch 2.02 R) drawn together to pitch 2 R about the axis and the
// lowest centre: neighbours touch. shuffled: see time_size.
dem::Particles packed_fill(const SlumpScene& scene, bool shuffled);

// shuffled: the particles' order randomly permuted (seeded), as after much mixing, instead of
// the lattice's own order (neighbours near in memory).
SizePoint time_size(const SlumpScene& scene, double particles, int steps, bool shuffled);

}  // namespace demscale::slump
