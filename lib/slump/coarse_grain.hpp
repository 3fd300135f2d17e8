// The coarse-grained scene of the particle-replacement concept (Yun & Park 2017, Eqs. 9–12): the
// same cone and fill height, particles of radius S_f·R (mass m·S_f³ from the same density, so the
// liquid per bridge of Eq. 5 scales as S_f³ and V̂ is unchanged), surface tension γ·S_f^k. Other
// parameters keep their physical value unless named in `scaled`: then they take the factor the
// basis implied by k demands (similarity/exponent_similarity). The time step follows the Rayleigh
// time, which grows with R̄ (and with 1/√E when E is scaled), so a coarse run takes fewer steps.
#pragma once

#include <string>
#include <vector>

#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct CoarseGraining {
    double sf = 1;                    // S_f
    double exponent = 1;              // k in γ̄ = γ S_f^k
    std::vector<std::string> scaled;  // of similarity::scalable_parameters()
};

// Throws InputError for S_f ≤ 0, an unknown scaled key, or particles that cannot pass the cone's
// top opening (2R̄ ≥ top diameter).
SlumpScene coarse_grained(const SlumpScene& fine, const CoarseGraining& c);

// Where geometry may start to matter (a warning beside a run): fewer than five particle diameters
// across the cone's top opening, a fill fewer than ten diameters high, or fewer than 200 particles.
std::vector<std::string> geometry_warnings(const SlumpScene& s, std::size_t particles);

// Whether particles of radius S_f·R pass the fine scene's top opening (2 S_f R < its diameter).
bool passes_opening(const SlumpScene& fine, double sf);

// Why S_f is geometry-limited in the fine scene's cone (none: it is usable): the coarse particles'
// top opening, fill height in diameters or spheres per fill (fill_mass over one sphere's) below the
// scene's [check] limits, or particles that do not pass the opening at all. A geometry-limited S_f
// is neither PASS nor FAIL of an exponent: the cone decides what its runs do.
std::vector<std::string> geometry_limits(const SlumpScene& fine, double sf);

// The candidates whose coarse scene is not geometry-limited, in their order.
std::vector<double> usable_scale_factors(const SlumpScene& fine, const std::vector<double>& candidates);

// Table 1's scale factors, the candidates a command's default --sf is drawn from.
inline const std::vector<double> table1_scale_factors = {1.4, 1.96, 2.74, 3.84};

}  // namespace demscale::slump
