// The coarse-grained scene of the particle-replacement concept (Yun & Park 2017, Eqs. 9–12): the
// same cone and fill height, particles of radius S_f·R (mass m·S_f³ from the same density, so the
// liquid per bridge of Eq. 5 scales as S_f³ and V̂ is unchanged), surface tension γ·S_f^k. Every
// other material parameter keeps its physical value.
#pragma once

#include "slump/slump_scene.hpp"

namespace demscale::slump {

// Throws InputError for S_f ≤ 0 or a particle too large for the cone (the scene's own check).
SlumpScene coarse_grained(const SlumpScene& fine, double sf, double exponent);

}  // namespace demscale::slump
