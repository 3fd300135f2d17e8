// What a slump test measures on a pile of equal spheres (SI units):
//  height       — highest particle top, max(z + R);
//  spread_d95   — diameter of the circle (around the pile's mass centre) holding 95 % of the
//                 particles' centres, plus one diameter for their extent: 2 (ρ₉₅ + R);
//  spread_max   — 2 (max ρ + R);
//  profile h(ρ) — highest top in radial bins of width 2R;
//  repose angle — atan of minus the least-squares slope of h(ρ) over the bins between 20 % and 80 %
//                 of the height (the flank, free of the top plateau and the foot).
#pragma once

#include <vector>

#include "dem/particles.hpp"

namespace demscale::slump {

struct ProfilePoint {
    double radius;  // bin centre, m
    double height;  // m (0 for an empty bin)
};

struct PileMeasures {
    double height = 0, spread_d95 = 0, spread_max = 0, repose_angle_deg = 0;
    std::vector<ProfilePoint> profile;
};

PileMeasures measure_pile(const dem::Particles& p);

}  // namespace demscale::slump
