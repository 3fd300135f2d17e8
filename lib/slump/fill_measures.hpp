// What the settled fill in the cone is like, so that fine and coarse fills can be compared:
//  mass           — the spheres' mass (the scene's fill_mass to the nearest sphere), kg;
//  height         — the fill's surface height (slump/measurements.hpp: independent of the radius), m;
//  solid_fraction — the spheres' volume over the cone's volume below that height (the bulk
//                   density over the solid density, wall layer included: what a scale would weigh);
//  core_fraction  — the share of random points (fixed seed), in the part of the fill at least one
//                   diameter from the cone wall, the floor and the top, that lie inside a sphere (the
//                   packing itself; 0 when that core is empty, as in very coarse fills);
//  coordination   — mean number of touching neighbours per sphere (sphere–sphere contacts only);
//  max_overlap    — the largest overlap between two spheres, relative to R.
#pragma once

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct FillMeasures {
    double top = 0;  // m, highest sphere top
    double mass = 0, height = 0;  // kg, m
    double solid_fraction = 0, core_fraction = 0, coordination = 0, max_overlap = 0;
    std::size_t core_points = 0;  // grid points sampled for core_fraction
};

// The mobile spheres of p (a rough floor's grains are ignored); all of one radius.
FillMeasures measure_fill(const dem::Particles& p, const SlumpScene& scene);

}  // namespace demscale::slump
