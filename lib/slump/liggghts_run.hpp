// A slump run whose lift and spread LIGGGHTS makes (docs/dem-engine.md, "LIGGGHTS"): demscale pours
// and settles the fill (the very fill its own run of the scene starts from), writes the deck
// (slump/liggghts_export.hpp), runs `mpirun -np N liggghts` on it, and measures the last snapshot of
// its dump as a pile (io/pile_file.hpp), with the slump test's own measures. SI units.
#pragma once

#include <functional>

#include "slump/slump_run.hpp"

namespace demscale::slump {

// The scene, lifted and spread by LIGGGHTS under mpirun with `ranks` ranks. Throws InputError,
// before any run, naming the keys LIGGGHTS cannot express (wet walls: LIGGGHTS' cohesion
// easo/capillary/viscous refuses walls), or a rank count outside 1 to 64.
void use_liggghts(SlumpScene& scene, int ranks, const std::string& ranks_field);

// What run_slump does for a scene with liggghts_ranks > 0. The deck, LIGGGHTS' log and its dump stay
// in phases.work_dir (a temporary folder, removed, when empty). The deck stops the spread when the
// pile is at rest by demscale's criterion, checked every quarter of the rest duration
// (slump/liggghts_export.hpp), or at the scene's spread time.
// Throws std::runtime_error naming mpirun or LIGGGHTS when either is missing or fails.
SlumpResult run_by_liggghts(const SlumpScene& scene, const std::function<void(const SlumpProgress&)>& progress, bool force_dt,
                            SlumpPhases phases);

}  // namespace demscale::slump
