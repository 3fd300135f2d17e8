// A mini-cone slump test scene (Kantro 1980 cone by default, issue #4's reference scene): the cone,
// the particles, their contact laws, the liquid and the protocol (fill, settle, lift, spread).
// Read from TOML (data/scenes/*.toml); units at that edge are mm, degrees, s, SI otherwise.
#pragma once

#include <string>
#include <vector>

#include "bridge/mikami.hpp"
#include "dem/material.hpp"
#include "similarity/particle_replacement.hpp"

namespace demscale::slump {

// How far a coarse run may differ from the fine reference (check-exponent's verdict), relative.
struct Tolerances {
    double slump = 0.10;    // |s̄ − s| / s
    double spread = 0.10;   // |d̄95 − d95| / d95
    double profile = 0.15;  // ‖h̄ − h‖₂ / ‖h‖₂ over the radius
};

// Which rolling-resistance law a scene uses (when rolling_resistance is on).
// epsd: Ai et al.'s k_r = 2.25 k_n μ_r² R*², no dashpot; epsd2: LIGGGHTS' epsd2, k_r = k_t R*²;
// constant_torque: Ai et al.'s model type A (LIGGGHTS' cdt).
enum class RollingModel { epsd, epsd2, constant_torque };

// How the cone is filled. poured: spheres inserted at random in batches and settled under gravity,
// then struck off level with the fill height (slump/pour.hpp), the default; lattice: a jittered hcp
// lattice cut to the cone (slump/fill.hpp), denser and crystalline, kept for comparison.
enum class FillKind { poured, lattice };

struct SlumpScene {
    std::string source;
    std::string dt_field = "run.dt_s";  // where dt came from, for messages ("file:line: run.dt_s")
    std::string name = "kantro-mini-slump";
    // Cone (open frustum on a flat floor).
    double bottom_diameter_m = 0.038, top_diameter_m = 0.019, height_m = 0.057;
    double lift_speed_m_per_s = 0.3, lift_height_m = 0.065;
    // Particles (monodisperse).
    double radius_m = 1e-3;
    double fill_height_m = 0.054;
    unsigned seed = 1;
    FillKind fill = FillKind::poured;
    dem::Material material{2200, 5e6, 0.3, 0.5, 0.5, 0.1, 0.3};  // η_r = 0.3: Ai's dashpot (epsd)
    bool rolling_resistance = true;
    RollingModel rolling_model = RollingModel::epsd;
    // Floor: a flat plane, or rough: one layer of fixed spheres of the fill's radius, centres on the
    // plane, on a jittered hexagonal lattice covering a disc (the usual base of repose-angle tests).
    bool rough_floor = false;
    double rough_floor_diameter_m = 0.15;
    // Liquid bridges.
    bool wet = true;
    bool wet_walls = false;  // Mikami's sphere–wall fit, unverified (2.5× the sphere–plane bound)
    similarity::Liquid liquid;
    bridge::MikamiOptions bridge;
    double viscosity_pa_s = 0;     // the liquid's μ for the bridge's viscous part; 0: static bridge only
    double min_gap_ratio = 0.01;   // s_min / R, the roughness gap of touching surfaces (viscous part)
    // Protocol.
    double dt_s = 1e-5;
    double gravity = 9.81;
    double settle_time_s = 0.3;    // at most; ends earlier once at rest
    double spread_time_s = 0.4;    // after the lift; ends earlier once at rest
    double pour_time_s = 0.3;      // per batch of the poured fill, at most; ends earlier once at rest
    double rest_speed_m_per_s = 1e-3;  // "at rest": all but (1 − rest_quantile) of the spheres slower than this…
    double rest_duration_s = 0.02;     // …for this long (slump/motion.hpp)
    double rest_quantile = 0.99;
    double skin_m = 0.3e-3;
    Tolerances tolerances;
    // The similarity table and Figs. 3-4 this scene implies (table, curves, regress, report):
    // the coarse radii S_f·R of Table 1 (S_f = 1.4^n) and the candidate exponents k of γ̄ = γ·S_f^k.
    std::vector<double> table_scale_factors{3.8416, 2.744, 1.96, 1.4, 1.0};
    std::vector<double> exponents{1.0, 3.0};
};

// The liquid per bridge V/R³ of the scene's wet contacts: Eq. 5 with the particle mass (the same
// for every S_f, since V scales with the mass).
double bridge_vhat(const SlumpScene& scene);

// The cone's inner radius at height z above the floor, m, and the volume inside it below z, m³.
double cone_radius_at(const SlumpScene& scene, double z);
double cone_volume_below(const SlumpScene& scene, double z);

// Throws InputError (file, line, key, value, accepted range) for a bad scene.
SlumpScene load_slump_scene(const std::string& path);

}  // namespace demscale::slump
