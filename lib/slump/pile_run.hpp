// A slump run made by any engine, measured as demscale measures its own runs (SI units;
// docs/slump-measures.md): the final pile and, for the slump, the settled fill it was lifted from.
// Both are measured on the scene's grid at the run's S_f, so a run made elsewhere gives the numbers
// a demscale run would have given for the same spheres, and its runs row joins demscale's own.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dem/particles.hpp"
#include "slump/measurements.hpp"
#include "slump/runs_file.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct PileRun {
    PileMeasures final;                 // the pile
    std::optional<double> fill_height;  // m, the fill's surface height; none without a fill
    double fill_mass = 0;               // kg: the fill's spheres (the pile's when no fill is given)
    double pile_mass = 0;               // kg
    double largest_radius = 0;          // m, of the pile's spheres
    std::vector<std::string> warnings;  // mass lost between fill and pile, a fill unlike the scene's

    // Slump over fill height; none without a fill.
    std::optional<double> slump_over_height() const;
};

// scene_at_sf: the scene coarse-grained to the run's S_f (its radius and grid). fill may be null.
// Throws InputError naming `sf_field` when the pile's median radius is more than 2 % from the
// scene's radius at that S_f (the run was made at another S_f): its measures would use the wrong foot.
PileRun measure_pile_run(const dem::Particles& pile, const dem::Particles* fill, const SlumpScene& scene_at_sf, double sf,
                         const std::string& sf_field);

// The run's row of a runs file: γ its own surface tension (N/m, 0: dry). Throws InputError naming
// `fill_field` when there is no fill height to take the slump from.
RunRow pile_run_row(const PileRun& run, double sf, double gamma, long seed, const SlumpScene& scene, const std::string& fill_field);

}  // namespace demscale::slump
