// A mini-cone slump test scene (Kantro 1980 cone by default, issue #4's reference scene): the cone,
// the particles, their contact laws, the liquid and the protocol (fill, settle, lift, spread).
// Read from TOML (data/scenes/*.toml); units at that edge are mm, degrees, s, SI otherwise.
#pragma once

#include <string>
#include <vector>

#include <span>

#include "dem/contact_settings.hpp"
#include "dem/law_parts.hpp"
#include "slump/size_distribution.hpp"

namespace demscale::slump {

// How far a coarse run may differ from the fine reference (check-exponent's verdict), relative.
struct Tolerances {
    double slump = 0.10;    // of the fill height: |s̄/H̄₀ − s/H₀|
    double spread = 0.10;   // |d̄95 − d95| / d95
    double profile = 0.15;  // ‖h̄ − h‖₂ / ‖h‖₂ over the radius
};

// Below these an S_f is geometry-limited (slump/coarse_grain.hpp): the cone, not the contact law,
// decides what its runs do, so they judge no exponent. The cone's top opening in particle
// diameters (the pour jams in it at 3.5 and 2.5 diameters in the reference scene and passes at 4.9),
// the fill height in diameters, and the spheres in one fill.
struct GeometryLimits {
    double opening_diameters = 4;
    double fill_diameters = 8;
    double particles = 200;
};

using RollingModel = dem::RollingModel;

// How the cone is filled. poured: spheres inserted at random in batches and settled under gravity,
// then cut to the fill's mass (slump/pour.hpp), the default; lattice: a jittered hcp lattice in the
// cone cut to the same mass (slump/fill.hpp), denser and crystalline, kept for comparison.
enum class FillKind { poured, lattice };

// The scene: its contact laws with their parameters (dem::ContactSettings), geometry and protocol.
struct SlumpScene : dem::ContactSettings {
    std::string source;
    std::string dt_field = "run.dt_s";  // where dt came from, for messages ("file:line: run.dt_s")
    std::string name = "kantro-mini-slump";
    // Cone (open frustum on a flat floor).
    double bottom_diameter_m = 0.038, top_diameter_m = 0.019, height_m = 0.057;
    double lift_speed_m_per_s = 0.3, lift_height_m = 0.065;
    // Particles: the reference radius (the one radius, or the distribution's mass median) and the
    // distribution's shape around it.
    double radius_m = 1e-3;
    SizeDistribution sizes;
    double fill_height_m = 0.054;
    // The fill's solid mass is this solid fraction of the cone's volume below fill_height_m, at the
    // particles' density: the same at every S_f (fill_mass).
    double fill_solid_fraction = 0.5;
    unsigned seed = 1;
    FillKind fill = FillKind::poured;
    // Floor: a flat plane, or rough: one layer of fixed spheres of the fill's radius, centres on the
    // plane, on a jittered hexagonal lattice covering a disc (the usual base of repose-angle tests).
    bool rough_floor = false;
    double rough_floor_diameter_m = 0.15;
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
    // The engine that lifts and spreads the fill: 0, demscale's; N > 0, LIGGGHTS under mpirun with N
    // ranks (the fill is poured and settled here either way: slump/liggghts_run.hpp).
    int liggghts_ranks = 0;
    Tolerances tolerances;
    GeometryLimits limits;
    // The similarity table and Figs. 3-4 this scene implies (table, curves, regress, report):
    // the coarse radii S_f·R of Table 1 (S_f = 1.4^n) and the candidate exponents k of γ̄ = γ·S_f^k.
    std::vector<double> table_scale_factors{3.8416, 2.744, 1.96, 1.4, 1.0};
    std::vector<double> exponents{1.0, 3.0};
};

// The liquid per bridge V/R³ of the scene's wet contacts: Eq. 5 with the particle mass (the same
// for every S_f, since V scales with the mass).
double bridge_vhat(const SlumpScene& scene);

// The smallest and largest sphere's radius, m (the time step's and the bridge reach's).
double smallest_radius(const SlumpScene& scene);
double largest_radius(const SlumpScene& scene);

// The cone's inner radius at height z above the floor, m, and the volume inside it below z, m³.
double cone_radius_at(const SlumpScene& scene, double z);
double cone_volume_below(const SlumpScene& scene, double z);

// The solid mass every fill of the scene holds, kg: ρ_s φ_fill V_cone(fill height), whatever the radius.
double fill_mass(const SlumpScene& scene);

// Throws InputError (file, line, key, value, accepted range) for a bad scene. The law parts'
// parameters are read from their tables (parts: the registered ones, dem/law_parts.hpp).
SlumpScene load_slump_scene(const std::string& path, std::span<const dem::LawPart> parts = dem::law_parts());

}  // namespace demscale::slump
