// The answer as a range: the exponents k for which a coarse run at γ̄ = γ S_f^k is equivalent to the
// fine run at the scene's γ within ±tolerance of slump over fill height, read from the transition
// model's response curve (stats/transition_model.hpp; docs/exponent-estimate.md, "The range of k").
// If the true exponent is k*, the coarse run at γ S_f^k slumps like the fine one at
// u = ln γ + (k − k*) ln S_f, so the predicted coarse − fine difference (dry offset removed) is
//   Δ(k; k*) = m(ln γ + (k − k*) ln S_f) − m(ln γ),  m the model's mean response.
// With δ− ≤ 0 ≤ δ+ the ends of {δ : |m(ln γ + δ ln S_f) − m(ln γ)| ≤ tolerance} (from 0 outward):
//  at k̂           — k in [k̂ + δ−, k̂ + δ+];
//  over k̂'s 95 % interval [a, b] (every k* in it must pass) — k in [b + δ−, a + δ+], empty when the
//                   interval is wider than the band.
// An end is open where the band reaches the end of the fine levels' range of ln γ before the
// tolerance: the data do not say how far it goes. Jointly: the intersection of every S_f's range.
// Only the slump enters: spread and profile have no response curve here.
#pragma once

#include <vector>

#include "stats/summary.hpp"
#include "stats/transition_model.hpp"

namespace demscale::stats {

struct PassingRange {
    double sf = 0;                  // 0: every S_f together
    Interval at_k_hat;              // k passing if k = k̂ exactly
    Interval over_interval;         // k passing for every k* in k̂'s interval (may be empty: low > high)
    bool low_open = false, high_open = false;  // an end set by the data's range, not by the tolerance
    bool empty() const { return !(over_interval.low <= over_interval.high); }
};

// log_gamma: ln of the scene's γ (N/m); fine_range: the fine levels' lowest and highest ln γ.
PassingRange passing_range(const TransitionFit& fit, double sf, double log_gamma, double tolerance, Interval fine_range);

// Per coarse curve from its own fit, then (with more than one) jointly: the intersection over every
// S_f of the ranges read from the joint fit. fits as fit_transition returns them.
std::vector<PassingRange> passing_ranges(const std::vector<TransitionFit>& fits, const std::vector<double>& sfs, double log_gamma,
                                         double tolerance, Interval fine_range);

}  // namespace demscale::stats
