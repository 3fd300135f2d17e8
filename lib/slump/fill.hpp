// Filling a cone with equal spheres: a hexagonal lattice (gap 2 % of R between neighbours) cut to
// the cone's inside and the fill height, each sphere jittered by up to 0.5 % of R per axis from a seeded
// generator. The same procedure for every radius, so fine and coarse start from equivalent states.
#pragma once

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

dem::Particles fill_cone(const SlumpScene& scene);

}  // namespace demscale::slump
