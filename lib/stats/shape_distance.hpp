// The profile criterion's distance between two ensembles of pile shapes (docs/verdicts.md): the
// L2 distance of their mean shapes over the norm of a reference mean shape,
//   D = ‖c̄ − f̄‖ / ‖n̄‖,
// with seed noise removed. The plain distance of two means is inflated by the noise of each:
// E ‖c̄ − f̄‖² = ‖μ_c − μ_f‖² + tr Σ_c / n_c + tr Σ_f / n_f, so two ensembles of the same pile sit
// a noise distance apart, and a bootstrap of it inflates it once more. The estimate subtracts the
// unbiased noise terms, S / n with S = Σ ‖x_i − x̄‖² / (n − 1) on each side, and takes the square
// root of what is left (0 when the noise explains it all). Its 95 % interval is the percentile
// bootstrap of the same corrected statistic over the seeds of both sides (a fixed generator seed,
// so a verdict repeats).
#pragma once

#include <cstddef>
#include <vector>

#include "stats/summary.hpp"

namespace demscale::stats {

struct ShapeEnsembles {
    std::vector<std::vector<double>> coarse, fine;  // the shapes compared, one per seed (equal lengths)
    std::vector<std::vector<double>> norm;          // the reference shapes whose mean is the norm (one per fine seed)
};

// On the seeds picked (indices into coarse and fine; norm follows fine). corrected: the noise terms
// subtracted (false: the plain distance of the means).
double shape_distance_of(const ShapeEnsembles& s, const std::vector<std::size_t>& coarse_pick, const std::vector<std::size_t>& fine_pick,
                         bool corrected = true);

// The corrected distance on every seed, and its 95 % percentile bootstrap interval.
struct ShapeDistance {
    double distance = 0, plain = 0;  // corrected, and the plain distance of the means
    Interval ci;
};
ShapeDistance measure_shape_distance(const ShapeEnsembles& s, int resamples = 2000, unsigned seed = 20261201);

}  // namespace demscale::stats
