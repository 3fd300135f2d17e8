// Filling a cone with equal spheres: a hexagonal lattice (gap 2 % of R between neighbours) cut to
// the cone's inside up to its top, then to the fill's mass (slump/pour.hpp), each sphere jittered by up to 0.5 % of R per axis from a seeded
// generator. The same procedure for every radius, so fine and coarse start from equivalent states.
// On a rough floor the first layer starts one diameter higher (above the floor's grains).
#pragma once

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

dem::Particles fill_cone(const SlumpScene& scene);

// The rough floor's grains (none for a flat floor): fixed spheres of the fill's radius and density,
// species 1, centres on z = 0, on a hexagonal lattice of pitch 2 R jittered by up to 5 % of R in x and
// y, covering a disc of the scene's rough_floor_diameter around the cone's axis.
dem::Particles floor_grains(const SlumpScene& scene);

}  // namespace demscale::slump
