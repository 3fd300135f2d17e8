// Where the Mikami regression can be trusted, and what to tell the user when it cannot.
// Mikami et al. (1998) state their fitted range in the original paper, which we could not consult;
// we use the range commonly quoted for this class of fits, V̂ ∈ [1e-5, 0.1], θ ≤ 40° (docs/model.md §2),
// and add the physical checks we can make ourselves.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bridge/mikami.hpp"

namespace demscale::bridge {

struct ValidityRange {
    double vhat_min = 1e-5;
    double vhat_max = 0.1;
    double theta_max_deg = 40.0;
};

// One machine-readable code and one sentence per finding.
struct ValidityWarning {
    std::string code;     // e.g. "vhat_below_range"
    std::string message;  // one line a person reads
};

// Warnings for evaluating the regression at (V̂, θ) with these coefficients:
//  vhat_below_range / vhat_above_range / theta_above_range — outside the fitted range;
//  theta_trend_unphysical — θ > 0 with V̂ < 0.06, where the fit's force grows with θ (docs/model.md §2);
//  negative_before_rupture — the fit turns negative before rupture and is clamped to 0;
//  above_physical_bound — F at contact exceeds 2πRγ·cos θ (sphere–sphere) or 4πRγ·cos θ (sphere–wall),
//                         the small-volume limit the force cannot exceed.
std::vector<ValidityWarning> check_validity(double vhat, ContactAngle theta, const MikamiCoefficients& k,
                                            const ValidityRange& range = {});

// "clamped" at gap ĥ: the fit is negative there before its rupture distance and is printed as 0.
std::optional<ValidityWarning> clamped_at(const MikamiCoefficients& k, double hhat);

}  // namespace demscale::bridge
