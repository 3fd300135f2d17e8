// When is a pile at rest, and what still moves when it is not. SI units.
// Rest criterion: the q-quantile of the mobile spheres' speeds |v| (default q = 0.99) below a rest
// speed. A quantile, not the maximum, so that a rattler or a sphere rolling away on the floor (at
// most 1 % of the pile) cannot keep a standing pile "moving"; the translational speed, not ω R,
// because the measures (height, spread, profile) depend on positions only.
#pragma once

#include <cstddef>

#include "dem/particles.hpp"

namespace demscale::slump {

// True when at most (1 − quantile) of the `mobile` spheres that are not fixed (in any order: fixed
// grains are not the pile) move at |v| ≥ speed. Stops counting as soon as the allowance is
// exceeded, so a moving pile costs a few spheres per call.
bool quantile_slower_than(const dem::Particles& p, std::size_t mobile, double speed, double quantile);

// What still moves: the spheres' speed |v| and rolling speed |ω| R (median, 99th percentile,
// maximum), how many move at ≥ rest_speed, and how many of those lie beyond the radius that holds
// 95 % of the pile (spheres rolling away or rattling at the edge, not the pile itself).
struct MotionSummary {
    double speed_p50 = 0, speed_p99 = 0, speed_max = 0;  // m/s
    double spin_p99 = 0;                                 // |ω| R, m/s
    std::size_t moving = 0, moving_at_edge = 0;
};
MotionSummary summarize_motion(const dem::Particles& p, std::size_t count, double rest_speed);

}  // namespace demscale::slump
