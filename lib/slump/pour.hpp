// The poured fill: how a slump cone is filled in the laboratory and in the LIGGGHTS, LAMMPS and
// Yade decks one compares with. Batches of spheres are inserted at random, non-overlapping
// positions above the pile (random sequential addition at a loose solid fraction, 0.3, inside the
// cone and in the column above its top opening), each batch falls and settles under gravity with
// the scene's own contact law, and batches follow until the cone holds the fill's mass and a layer
// more; then the fill is cut to its mass: of the spheres wholly inside the cone, the lowest centres
// are kept until they weigh the scene's fill_mass (to the nearest sphere), each size bin of a
// distribution to its share (slump/size_distribution.hpp). Radii are drawn by number from the
// scene's distribution (one radius draws none). Every S_f's fill holds the
// same mass; a cut through the centres loses nothing that grows with the radius (striking off every
// sphere whose top pokes above a level left a coarse fill 5 % lighter at S_f 1.96). A looser coarse
// packing stands a little higher instead; its fill height is measured and reported
// (slump/fill_measures.hpp).
// Between batches the engine is rebuilt with the new spheres: contact history (tangential springs,
// bridges stretched across a gap) starts afresh there, as it does after the strike-off.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// A fill the cone cannot hold at the scene's mass (the pour jammed, or the spheres do not fit): the
// run is unusable as a column, which a study reports instead of comparing it.
struct FillShortfall : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Spheres still to insert: what the cone lacks of the fill's volume plus a layer one diameter thick
// at a solid fraction of 0.5 over its cross-section at the fill height; 0 once it holds that.
std::size_t pour_batch_size(const SlumpScene& scene, const dem::Particles& pile);

// `count` new spheres (radii drawn from the scene's distribution, its density) at random positions that overlap neither
// each other nor the pile, from just above the pile's top upward; `stream` seeds the generator
// together with the scene's seed. Inside the cone below its top, in the cylinder of the top
// opening above it.
dem::Particles insert_batch(const SlumpScene& scene, const dem::Particles& pile, std::size_t count, unsigned stream);

// Of the spheres inside the cone's wall with their centres under its top, those with the lowest
// centres that weigh fill_mass(scene) to the nearest sphere, each size bin its share (short of
// it: from the spheres pressed less than 5 % of R into the wall, then from any bin). Throws std::runtime_error naming the
// radius (FillShortfall) when the cone holds less by more than half a sphere and 0.5 % (the pour
// jammed in the top opening, or the fill does not fit under the cone's top).
dem::Particles cut_to_mass(const SlumpScene& scene, const dem::Particles& pile);

// Pours and cuts to the fill's mass. settle(pile) runs the engine on the pile with the cone in place until rest
// (or the scene's pour_time_s) and returns the mobile spheres. At most 8 batches.
dem::Particles pour_fill(const SlumpScene& scene, const std::function<dem::Particles(dem::Particles)>& settle);

}  // namespace demscale::slump
