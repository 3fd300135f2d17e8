// The plastic limit of the tangential (Coulomb) and rolling springs: does |x| exceed `limit`?
#pragma once

#include <cmath>

namespace demscale::dem {

// |x| when it exceeds limit (≥ 0), else 0, from |x|² (norm2). Well inside the limit, the common
// case of a sticking contact, it takes no square root: below limit²·(1 − 1e-12) the rounded |x|
// cannot exceed limit either, so the answer is the exact test's, bit for bit (NaN included).
inline double beyond_limit(double norm2, double limit) {
    if (norm2 < limit * limit * (1.0 - 1e-12)) return 0.0;
    const double norm = std::sqrt(norm2);
    return norm > limit ? norm : 0.0;
}

}  // namespace demscale::dem
