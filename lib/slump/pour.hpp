// The poured fill: how a slump cone is filled in the laboratory and in the LIGGGHTS, LAMMPS and
// Yade decks one compares with. Batches of spheres are inserted at random, non-overlapping
// positions above the pile (random sequential addition at a loose solid fraction, 0.3, inside the
// cone and in the column above its top opening), each batch falls and settles under gravity with
// the scene's own contact law, and batches follow until the pile covers the fill height; then the
// cone is struck off level: every sphere not wholly below the fill height, or outside the cone, is
// removed. The same protocol at every S_f, so fine and coarse fills are comparable (their solid
// fraction and coordination number are measured, slump/fill_measures.hpp).
// Between batches the engine is rebuilt with the new spheres: contact history (tangential springs,
// bridges stretched across a gap) starts afresh there, as it does after the strike-off.
#pragma once

#include <cstddef>
#include <functional>

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// Spheres still to insert: 0 once the spheres reaching above the strike level (centre above it less
// R) hold the solid volume of a layer one diameter thick at a solid fraction of 0.5 over the cone's
// cross-section there. The first batch is a loose fill's worth (solid fraction 0.45 under the strike
// level, plus that layer); later ones fill what is missing above the pile's level at the pile's own
// solid fraction. Little overfill, so little spills over the cone's rim.
std::size_t pour_batch_size(const SlumpScene& scene, const dem::Particles& pile);

// `count` new spheres (radius and density of the scene) at random positions that overlap neither
// each other nor the pile, from just above the pile's top upward; `stream` seeds the generator
// together with the scene's seed. Inside the cone below its top, in the cylinder of the top
// opening above it.
dem::Particles insert_batch(const SlumpScene& scene, const dem::Particles& pile, std::size_t count, unsigned stream);

// The spheres wholly below the fill height and inside the cone.
dem::Particles strike_off(const SlumpScene& scene, const dem::Particles& pile);

// Pours and strikes off. settle(pile) runs the engine on the pile with the cone in place until rest
// (or the scene's pour_time_s) and returns the mobile spheres. At most 8 batches.
dem::Particles pour_fill(const SlumpScene& scene, const std::function<dem::Particles(dem::Particles)>& settle);

}  // namespace demscale::slump
