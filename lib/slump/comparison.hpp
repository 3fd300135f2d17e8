// A coarse-grained slump run against the fine reference: relative errors of the measures the
// slump test reports, and the speed-up. Profiles have bins of 2R̄ and 2R; the coarse one is
// interpolated linearly onto the fine bin centres (zero beyond its last bin) before the L2 norm.
#pragma once

#include "slump/slump_run.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct RunComparison {
    double slump_error = 0;     // (s̄ − s) / s, signed
    double spread_error = 0;    // (d̄95 − d95) / d95, signed
    double profile_error = 0;   // ‖h̄ − h‖₂ / ‖h‖₂ on the fine bins (uniform in radius)
    double wall_speedup = 0;    // fine wall time / coarse wall time
    double work_speedup = 0;    // fine particle-steps / coarse particle-steps
    bool within(const Tolerances& t) const;
};

RunComparison compare_runs(const SlumpResult& fine, const SlumpResult& coarse);

// h(ρ) of a profile at any radius: linear between bin centres, the first bin's height inside it,
// zero beyond the last bin.
double profile_height_at(const std::vector<ProfilePoint>& profile, double radius);

}  // namespace demscale::slump
