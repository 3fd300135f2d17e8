// The exponent k of γ̄ = γ S_f^k measured from response curves (docs/exponent-estimate.md).
//
// A response curve is a measured response y (for the slump test: slump over fill height) of an
// ensemble of seeds at several values x = ln γ of the cohesion variable. If k is the right
// exponent, the coarse curve at scale factor S_f is the fine curve shifted by Δ = k ln S_f along x:
// y_coarse(x) = y_fine(x − k ln S_f).
//
// Estimator (least squares on a shift): the fine curve is the monotone cubic interpolant (Steffen
// 1990, GSL) of its ensemble means (linear for two levels), held flat beyond its first and last level (the plateaus of a pile that stands
// and one that has fully slumped); k̂ minimises Σ_j (ȳ_j − y_fine(x_j − k ln S_f))² over the coarse
// levels j, per S_f, and jointly over all S_f (one k, every coarse level). The search runs over
// [k_min, k_max] on a grid of 0.05 refined by golden section. 95 % interval: percentile bootstrap
// over seeds (each curve's seeds resampled with replacement, a seed's runs at every level and in
// the control together; fine and coarse curves independently; k̂ recomputed), with a fixed
// generator seed so that an estimate repeats. k is undetermined when the objective is flat
// at its minimum (the coarse levels lie on the plateaus: many shifts fit equally) or the interval
// reaches the search bounds.
//
// Baseline: a curve may carry a control, the same response of the same seeds without the cohesion
// (for the slump test: the dry scene). When the fine curve and a coarse curve both carry one, the
// coarse means are compared after subtracting the offset mean(coarse control) − mean(fine control):
// the difference that S_f makes without any cohesion is not booked as a shift in k. The bootstrap
// resamples the controls' seeds too, so the interval carries the offset's uncertainty.
//
// Split levels: a level whose seeds fall at both ends of the response (a column that stood and one
// that slumped at the same cohesion) is a coin toss that a bootstrap over a few seeds cannot weigh:
// the interval then understates the uncertainty, and the estimate says how many such levels it
// rests on.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

#include "stats/summary.hpp"

namespace demscale::stats {

struct ResponseLevel {
    double x = 0;               // ln of the cohesion variable (for γ in N/m: ln γ)
    std::vector<double> y;      // the response, one value per seed
    std::vector<long> seed;     // the seed of each y (empty: y[i] is seed i)
    long seed_at(std::size_t i) const { return seed.empty() ? static_cast<long>(i) : seed[i]; }
};

// A curve's levels (and its control) share their seeds: a seed's runs at every level are one unit
// of the bootstrap (resample_by_seed).
struct ResponseCurve {
    double sf = 1;                     // scale factor of its particles (fine: 1)
    std::vector<ResponseLevel> levels; // in any order
    ResponseLevel control;             // the response without cohesion, one value per seed (no y: none); x unused
    std::vector<long> seeds() const;   // every seed of its levels and control, once each, ascending
};

// The curve with its seeds drawn with replacement, as many as it has: every level (and the control)
// takes the drawn seeds' values, a seed drawn twice counted twice. A level that lacks every drawn
// seed is drawn again (up to 100 tries; then it keeps its own values).
ResponseCurve resample_by_seed(const ResponseCurve& c, std::mt19937_64& rng);

// mean(coarse.control) − mean(fine.control), 0 unless both carry a control.
double control_offset(const ResponseCurve& fine, const ResponseCurve& coarse);

struct ShiftSearch {
    double k_min = -2, k_max = 6;
    int resamples = 1000;
    unsigned seed = 20170101;  // of the bootstrap's generator
};

struct ExponentEstimate {
    double sf = 0;            // 0 for the joint estimate over every S_f
    double k = 0;             // k̂
    Interval ci;              // 95 % percentile bootstrap interval
    double rms = 0;           // root mean square residual of the coarse means at k̂
    double offset = 0;        // the control offset subtracted from the coarse means (one S_f; 0 jointly or without controls)
    bool determined = false;  // a unique minimum, and the interval inside the search bounds
    std::size_t split_levels = 0;  // levels it rests on (the fine curve's and its coarse curves') that split
};

// A level with seeds at both ends of the response: at least one in the lowest third of the span of
// all the curves' level means (fine and coarse) and at least one in the highest third.
struct SplitLevel {
    double sf = 1;  // its curve's scale factor (fine: 1)
    double x = 0;
    std::size_t low = 0, high = 0, seeds = 0;  // seeds in the lowest third, in the highest, in all
};

// The split levels of the fine curve, then of each coarse curve (in their order, levels as given).
std::vector<SplitLevel> split_levels(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse);

// Throws std::invalid_argument for a fine curve with fewer than two levels, a coarse curve with
// S_f ≤ 1 or no levels, or a level without runs or with a non-finite x.
void check_response_curves(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse);

// The fine curve's value at x: the interpolant through the levels' means, flat beyond them.
double interpolate_response(const ResponseCurve& fine, double x);

// Root mean square residual of the coarse curves' means against the fine curve shifted by
// k ln S_f: what k̂ minimises, and how far a given k (of a similarity group) is from the data.
double shift_residual_rms(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse, double k);

// k̂ with its interval for each coarse curve, then (with more than one) jointly: one entry per
// coarse curve in their order, the joint one last. Throws std::invalid_argument for a fine curve
// with fewer than two levels, a coarse curve with S_f ≤ 1 or no levels, or an empty ensemble.
std::vector<ExponentEstimate> estimate_exponent(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse,
                                                const ShiftSearch& search = {});

}  // namespace demscale::stats
