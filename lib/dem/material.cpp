#include "dem/material.hpp"

#include <cmath>
#include <numbers>

namespace demscale::dem {

double damping_ratio(double e) {
    if (e >= 1.0) return 0.0;
    const double l = std::log(e);
    return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

}  // namespace demscale::dem
