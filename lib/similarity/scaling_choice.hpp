// Exact and partial similarity (Feng et al. 2009; Feng & Owen 2014). Exact similarity scales every
// quantity by the factor its dimension demands; partial similarity holds some quantities at their
// physical value (gravity, Young's modulus, …), which breaks the similarity conditions whose
// demanded factor is not 1.
#pragma once

#include <string>
#include <vector>

#include "similarity/dimension.hpp"
#include "similarity/quantity_catalogue.hpp"

namespace demscale::similarity {

struct ScalingChoice {
    ScaleBasis basis;
    std::vector<std::string> held;  // catalogue keys kept at their physical value
};

// The basis with S_L = length_factor in which both named quantities keep their physical value
// (e.g. "gravity" and "density" give S_ρ = 1, S_T = √S_L). Solved in log space (Eigen);
// throws InputError when the two do not fix S_ρ and S_T (e.g. "stress" and "youngs_modulus").
ScaleBasis basis_keeping(double length_factor, std::string_view first, std::string_view second);

struct QuantityScaling {
    const Quantity* quantity = nullptr;
    double required = 1;  // factor exact similarity demands: S_L^a S_ρ^b S_T^c
    double applied = 1;   // factor the model uses (1 when held)
    bool held = false;
    bool broken = false;  // held although similarity demands a factor ≠ 1
};

// One row per catalogue quantity. Throws InputError for an unknown held key or a non-positive basis.
std::vector<QuantityScaling> evaluate_scaling(const ScalingChoice& choice);

}  // namespace demscale::similarity
