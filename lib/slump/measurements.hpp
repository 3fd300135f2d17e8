// What a slump test measures on a pile of equal spheres (SI units; fixed spheres, a rough floor's
// grains, are not part of the pile and are ignored):
//  height       — highest particle top, max(z + R);
//  spread_d95   — diameter of the circle (around the pile's mass centre) holding 95 % of the
//                 particles' centres, plus one diameter for their extent: 2 (ρ₉₅ + R);
//  spread_max   — 2 (max ρ + R);
//  profile h(ρ) — highest top in radial bins of width 2R;
//  repose angle — atan of minus the least-squares slope of h(ρ) over the bins whose height above the
//                 foot (the top of a lone sphere on the floor) lies between 20 % and 80 % of the
//                 pile's height above it: the flank, free of the top plateau and of the one-sphere-
//                 high fringe that rolled away (which matters when the pile is few spheres high).
#pragma once

#include <optional>
#include <vector>

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct ProfilePoint {
    double radius;  // bin centre, m
    double height;  // m (0 for an empty bin)
};

struct PileMeasures {
    double height = 0, spread_d95 = 0, spread_max = 0;
    double foot = 0;  // the top of a lone sphere on the floor, m (as passed to measure_pile)
    std::optional<double> repose_angle_deg;  // none where the flank has fewer than two bins (no slope)
    std::vector<ProfilePoint> profile;
};

// foot: the top of a lone sphere on the floor, m (lone_sphere_top of the scene).
PileMeasures measure_pile(const dem::Particles& p, double foot);

// 2 R on a flat floor; (1 + 2√(2/3)) R in a hollow of the rough floor's close-packed grains.
double lone_sphere_top(const SlumpScene& scene);

}  // namespace demscale::slump
