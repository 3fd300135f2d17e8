// The exponent k of γ̄ = γ S_f^k from a model of the slump test's two responses
// (docs/exponent-estimate.md, "The transition model"). Near the cohesion where a column just holds,
// a run either stands or slumps: the response is bimodal, and the means of a few seeds are coin
// tosses. The model treats the two parts apart, in u = ln γ − k ln S_f (a coarse run at γ̄ behaves
// like a fine run at γ̄ / S_f^k):
//  quantal    — a run stands when its slump is below `stands_below` of the fill height;
//               P(stand) = Φ((u − θ) / w), a probit in u with one threshold θ and one width w for
//               every curve (the coarse threshold is the fine one moved by k ln S_f);
//  continuous — the slump of the runs at levels where none stood (the slumped branch; a column that
//               just fails where others stand slumps differently: on the reference scene the fine
//               runs that slumped at 2γ, where half stood, slumped 0.535 of the height, more than
//               at γ): y = β₀ + β₁ v + β₂ v² + b_S, v = u − ū,
//               residual sd σ (β₂ with three or more fine levels that hold slumped runs, β₁ with two); b_S is the
//               dry offset of S_f, b_S = d_S − d₁, where the dry controls enter as y = d_S with their
//               own sd σ_dry (no control: b_S = 0).
// Runs are independent given the model: the fill is poured anew at every γ, so a seed's runs at
// two levels share only the pour's random start. k̂ maximises the log-likelihood ℓ(k) = ℓ_quantal +
// ℓ_continuous, the nuisance parameters maximised at each k (a probit fit by Newton's method, a
// weighted least-squares fit with the two sd's re-estimated); the 95 % interval is the profile
// likelihood's, {k : 2 (ℓ(k̂) − ℓ(k)) ≤ c}, c = χ²₁(0.95) = 3.84 or, with few slumped runs, the
// larger n ln(1 + F₁,ₙ₋ₚ / (n − p)) that is exact for a linear model with σ estimated. The threshold width is kept ≥ 0.02 in ln γ:
// where no stand/slump pair crosses (separated runs) the likelihood is flat in θ and the width
// would shrink to nothing.
#pragma once

#include <cmath>
#include <vector>

#include "stats/curve_shift.hpp"

namespace demscale::stats {

struct TransitionSettings {
    double stands_below = 0.3;  // slump / fill height below which a column counts as standing
    double k_min = -2, k_max = 6;
    double min_width = 0.1;     // of the probit in ln γ
};

struct TransitionFit {
    double sf = 0;             // 0: jointly over every S_f
    double k = 0;              // k̂
    Interval ci;               // 95 %: the profile interval widened to the seed jackknife's where that is wider
    Interval profile_ci;       // 95 % profile likelihood interval
    double cutoff = 0;         // the deviance it admits
    double jackknife_se = NAN; // delete-one-seed jackknife standard error of k̂ (NaN: fewer than 3 seeds in all)
    std::size_t jackknife_dof = 0;
    bool extrapolated = false; // a coarse curve's slumped runs lie mostly beyond the fine levels at k̂
    bool determined = false;   // the interval closes inside [k_min, k_max]
    double threshold = 0;      // θ: fine ln γ where P(stand) = ½ (at k̂; NaN without stand and slump both)
    double width = 0;          // w, ln γ
    std::vector<double> branch;  // β₀, β₁[, β₂] of the slumped branch at k̂, in v = u − centre
    double centre = 0;           // ū
    double sigma = 0;            // residual sd of the slumped runs, of the fill height
    std::vector<double> offsets; // b_S at k̂ per coarse curve, in their order (0 without controls)
    double standing_slump = 0;   // mean slump of the standing runs, of the fill height
    std::size_t standing = 0, slumped = 0;  // runs of each kind it rests on
    std::size_t on_branch = 0;               // slumped runs at levels where none stood (the continuous part)
    bool quantal = false;      // the quantal part took part (runs of both kinds)
    std::vector<double> profile_k, profile_deviance;  // 2 (ℓ(k̂) − ℓ(k)) on the search grid
};

// P(stand) at u (fine ln γ) of a fit: 0 or 1 on one side without the quantal part.
double stand_probability(const TransitionFit& fit, double u);
// The slumped branch at u, and the mean response (1 − P)·branch + P·standing_slump.
double slumped_branch(const TransitionFit& fit, double u);
double mean_response(const TransitionFit& fit, double u);

// One fit per coarse curve, then (with more than one) jointly, as estimate_exponent. Throws
// std::invalid_argument as estimate_exponent does.
std::vector<TransitionFit> fit_transition(const ResponseCurve& fine, const std::vector<ResponseCurve>& coarse,
                                          const TransitionSettings& settings = {});

}  // namespace demscale::stats
