// A slump run against the fine ensemble: the differences of the measures the slump test reports,
// in measures that favour no scale, and the speed-up.
//  slump   — slump over the fill's initial height, s/H₀ (the coarse run's minus the fine mean);
//  spread  — the pile's diameter at half its height (slump/measurements.hpp), relative to the fine mean;
//  profile — distance of the pile's shape from the fine mean shape, ‖h̄ − h‖₂ / ‖h‖₂ over the
//            radius (fine bins of 2R). A pile's shape is its profile (highest top per bin) with two
//            rules that keep the particle size out of it: heights no more than half a coarse radius
//            above a lone coarse sphere's top (1.25 × 2R̄ on a flat floor, the coarser run's single
//            layer) count as zero in both piles, so a one-particle fringe, 2R high in a fine pile and
//            2R̄ in a coarse one, counts for neither and both are compared at the coarser resolution;
//            and empty bins are bridged by linear interpolation between their occupied neighbours,
//            so the gaps between a coarse pile's few outer spheres are no holes. Beyond the outermost
//            occupied bin the shape is zero (docs/slump-measures.md).
#pragma once

#include <vector>

#include "slump/slump_run.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// The shape of a pile (see above) at the given radii, m; heights at or below `floor_level` count zero.
std::vector<double> pile_shape(const PileMeasures& pile, const std::vector<double>& radii, double floor_level);

// The single-layer level of a comparison: 1.25 × the larger of the two runs' lone-sphere tops, m.
double fringe_level(const PileMeasures& a, const PileMeasures& b);

// ‖a − reference‖₂ / ‖reference‖₂ (0 when the reference is all zero).
double shape_distance(const std::vector<double>& a, const std::vector<double>& reference);

// What the fine ensemble is, as one reference: means of its measures and of its shapes.
struct FineReference {
    double slump_over_height = 0, spread = 0;  // means
    double wall_s = 0, particle_steps = 0;         // means, for the speed-ups
    std::vector<double> radii;                     // bin centres of width 2R, reaching every run's pile
    std::vector<PileMeasures> piles;               // the fine runs' final piles
    // Mean shape of the fine piles on `radii`, heights at or below floor_level counted zero, m.
    std::vector<double> shape(double floor_level) const;
};
// radius: the fine particles' radius, m. extra_reach: the largest spread_max of the runs that will
// be compared, so that the grid covers them too.
FineReference fine_reference(const std::vector<const SlumpResult*>& fine, double radius, double extra_reach = 0);

struct RunComparison {
    double slump_error = 0;    // s̄/H̄₀ − mean(s/H₀), signed, a fraction of the fill height
    double spread_error = 0;   // (d̄ − mean d) / mean d, signed
    double profile_error = 0;  // shape distance from the fine mean shape
    double wall_speedup = 0;   // mean fine wall time / this run's wall time
    double work_speedup = 0;   // mean fine particle-steps / this run's particle-steps
};

RunComparison compare_to(const FineReference& fine, const SlumpResult& run);

// h(ρ) of a profile at any radius: linear between bin centres, the first bin's height inside it,
// zero beyond the last bin.
double profile_height_at(const std::vector<ProfilePoint>& profile, double radius);

}  // namespace demscale::slump
