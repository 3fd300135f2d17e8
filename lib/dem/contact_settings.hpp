// The contact laws of a scene and the values of their parameters, SI: which law parts act (rolling
// model, wet or dry, wet walls, the bridge's printed form and rupture law) and what the parameter
// tables of dem/law_parts.hpp read and write. A slump scene is one of these plus its geometry and
// protocol.
#pragma once

#include <string_view>

#include "bridge/bridge_curve.hpp"
#include "dem/material.hpp"
#include "similarity/particle_replacement.hpp"

namespace demscale::dem {

// Which rolling-resistance law acts (when rolling_resistance is on). epsd: Ai et al.'s model C,
// k_r = 2.25 k_n μ_r² R*², with its dashpot; epsd2: LIGGGHTS' epsd2, k_r = k_t R*²;
// constant_torque: Ai et al.'s model A (LIGGGHTS' cdt).
enum class RollingModel { epsd, epsd2, constant_torque };

// The liquid bridge's normal lubrication: Pitois et al.'s (2000) finite-volume form, or the
// unbounded 6π μ R*² v / s that LIGGGHTS' easo/capillary/viscous uses (dem/laws/cohesion.hpp).
enum class Lubrication { unbounded, finite_volume };

struct ContactSettings {
    Material material{2200, 5e6, 0.3, 0.5, 0.5, 0.1, 0.3};  // η_r = 0.3: Ai's dashpot (epsd)
    std::string_view normal_law = "hertz";  // contact.normal_law: a registered normal part's choice (dem/law_parts.hpp)
    bool rolling_resistance = true;
    RollingModel rolling_model = RollingModel::epsd;
    bool wet = true;          // liquid bridges between particles
    bool wet_walls = false;   // and to the walls
    similarity::Liquid liquid;
    bridge::MikamiOptions bridge;  // the fit's printed form and rupture law (particle_curve = fit)
    bridge::CurveSource particle_curve = bridge::CurveSource::fit;  // bridge_variant = "table": exact
    bridge::CurveSource wall_curve = bridge::CurveSource::exact;    // wall_bridge = "mikami1998": fit
    double viscosity_pa_s = 0;    // the liquid's μ for the bridge's viscous part; 0: static bridge only
    double min_gap_ratio = 0.01;  // s_min / R, the roughness gap of touching surfaces (viscous part)
    Lubrication lubrication = Lubrication::finite_volume;  // liquid.lubrication
    double cohesion_energy_density = 0;  // k_c, J/m³, of the simplified JKR adhesion (dry scenes); 0: none
};

// The sizes a contact law is built for, m: the reference radius (the one radius, or a size
// distribution's mass median: the roughness gap) and the largest sphere (a bridge's reach).
struct LawSizes {
    double radius_m;
    double largest_radius_m;
};

}  // namespace demscale::dem
