// The free surface of a pile, measured so that the same shape built from spheres of any radius
// measures the same (docs/slump-measures.md). SI units.
//
// The pile is cut into coaxial annuli of a fixed width (a length of the scene, not of the spheres).
// In each annulus the solid fraction φ(z) is the exact area of the spheres' horizontal sections
// that falls inside the annulus at height z (circle–circle intersections, no sampling), over the
// annulus' area. The surface height of an annulus is its Gibbs dividing surface: the height a
// column at the pile's bulk solid fraction φ_b would have to hold the solid found above a level a
// few radii under the top,
//     h = z_a + ∫_{z_a}^{∞} φ(z) dz / φ_b .
// For a packing cut by a surface through the sphere centres this is the cut itself, whatever the
// radius: a sphere's section area is symmetric about its centre, so the solid that pokes above
// the cut equals the gap left below it. φ_b is the pile's own bulk solid fraction (annuli deep
// enough to have a bulk), so a looser coarse packing does not read as a lower surface.
#pragma once

#include <vector>

#include "dem/particles.hpp"

namespace demscale::slump {

struct SurfaceGrid {
    double bin_width = 0;    // annulus width, m
    double axis_radius = 0;  // the pile's height is the surface's mean over the disc of this radius, m
};

struct PileSurface {
    std::vector<double> radii;    // annulus centres, m
    std::vector<double> heights;  // surface height per annulus, m (0 where the annulus holds no solid)
    double bulk_fraction = 0;     // φ_b
    double height = 0;            // area-weighted mean of the heights over the axis disc, m
    // Twice the outermost radius where the surface stands at `spread_level` of the height, m
    // (linear between annulus centres): the pile's diameter at half its height.
    double spread = 0;
};

inline constexpr double spread_level = 0.5;

// The surface of the spheres of p (all of them: pass the mobile ones) around (cx, cy), the pile's
// axis. Throws std::invalid_argument for a grid with a non-positive width.
PileSurface pile_surface(const dem::Particles& p, double cx, double cy, const SurfaceGrid& grid);

// Area of the intersection of a disc of radius a and a disc of radius b whose centres are d apart.
double disc_overlap_area(double a, double b, double d);

}  // namespace demscale::slump
