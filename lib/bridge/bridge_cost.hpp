// Benchmark helper (not for tests): wall time of one force evaluation of a bridge model at a fixed
// pair type (V̂, θ), the DEM situation, over gaps spread across [0, ĥ_rupture].
#pragma once

#include "bridge/bridge_model.hpp"

namespace demscale::bridge {

// Median over `repeats` runs, each sized (after a short calibration) to last about `seconds_per_run`;
// ns per call. The checksum defeats dead-code elimination.
struct EvaluationCost {
    double ns_per_evaluation = 0;
    long evaluations_per_run = 0;
    double checksum = 0;
};
EvaluationCost measure_evaluation_cost(const BridgeModel& model, double vhat, ContactAngle theta,
                                       double seconds_per_run = 0.2, int repeats = 5);

}  // namespace demscale::bridge
