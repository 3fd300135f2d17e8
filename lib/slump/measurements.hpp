// What a slump test measures on a pile (SI units; fixed spheres, a rough floor's grains, are not
// part of the pile and are ignored). The measures a comparison uses do not depend on the sphere
// size: two piles of one shape built from spheres of different radii measure the same
// (slump/pile_surface.hpp, docs/slump-measures.md):
//  height       — the free surface's mean height over the axis disc (the cone's top opening);
//  spread       — the pile's diameter where its surface stands at half that height;
//  profile h(ρ) — the free surface per annulus of the scene's width (a sixteenth of the top opening);
//  repose angle — atan of minus the least-squares slope of h(ρ) over the annuli whose surface lies
//                 between 20 % and 80 % of the height: the flank, free of the top plateau and of a
//                 one-sphere fringe.
// The sphere-level measures they replace stay, named as such, for comparison: each grows with the
// radius (a coarse pile's highest top stands out by about (S_f − 1) R more):
//  height_top   — highest particle top, max(z + R);
//  spread_d95   — 2 (ρ₉₅ + R): the circle around the mass centre holding 95 % of the centres, plus R;
//  spread_max   — 2 (max ρ + R);
//  profile_tops — highest top in radial bins of width 2R.
#pragma once

#include <optional>
#include <vector>

#include "dem/particles.hpp"
#include "slump/pile_surface.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct ProfilePoint {
    double radius;  // bin centre, m
    double height;  // m (0 for an empty bin)
};

struct PileMeasures {
    double height = 0, spread = 0;              // m, size-independent
    std::vector<ProfilePoint> profile;           // the surface, m
    std::optional<double> repose_angle_deg;     // none where the flank has fewer than two annuli (no slope)
    double bulk_fraction = 0;                    // the pile's bulk solid fraction, as the surface found it
    double height_top = 0, spread_d95 = 0, spread_max = 0;  // sphere-level, m (see above)
    std::vector<ProfilePoint> profile_tops;      // sphere-level, m
    double foot = 0;  // the top of a lone sphere on the floor, m (as passed to measure_pile)
};

// foot: the top of a lone sphere on the floor, m (lone_sphere_top of the scene); grid: the surface's
// annuli and axis disc (surface_grid of the scene).
PileMeasures measure_pile(const dem::Particles& p, double foot, const SurfaceGrid& grid);
// With the scene's foot and grid.
PileMeasures measure_pile(const dem::Particles& p, const SlumpScene& scene);

// 2 R on a flat floor; (1 + 2√(2/3)) R in a hollow of the rough floor's close-packed grains.
double lone_sphere_top(const SlumpScene& scene);

// Annuli a sixteenth of the cone's top opening wide; the height's disc is the opening itself. A length
// of the cone, so fine and coarse piles of a scene are measured on one grid.
SurfaceGrid surface_grid(const SlumpScene& scene);

}  // namespace demscale::slump
