// Walls particles collide with, using the same contact laws as particle pairs (R* = R, m* = m,
// the wall as a partner of radius 0 at the closest point of its surface).
//  PlaneWall   — infinite, one-sided: particles live on the side its normal points to.
//  FrustumWall — a thin open cone frustum (a cylinder when both radii are equal) around a vertical
//                axis, touched from either side; it can translate with a prescribed velocity during
//                a time window (the slump cone being lifted). Analytic, no mesh.
#pragma once

#include <algorithm>
#include <cmath>
#include <variant>

#include "dem/particles.hpp"

namespace demscale::dem {

struct PlaneWall {
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ();  // unit, pointing into the domain
};

struct FrustumWall {
    Vec3 base_centre = Vec3::Zero();  // centre of the bottom circle at t = 0, m
    double bottom_radius = 0.019;     // m
    double top_radius = 0.0095;       // m
    double height = 0.057;            // m
    Vec3 velocity = Vec3::Zero();     // translation while moving, m/s
    double move_start = 0;            // s
    double move_end = 0;              // s (no motion when move_end <= move_start)

    // Displacement of the wall at time t, m.
    Vec3 offset(double t) const {
        if (move_end <= move_start) return Vec3::Zero();
        return velocity * (std::clamp(t, move_start, move_end) - move_start);
    }
    Vec3 velocity_at(double t) const {
        return (move_end > move_start && t >= move_start && t < move_end) ? velocity : Vec3::Zero();
    }
    // Where the point (ρ, z) (m, relative to the base centre, ρ from the axis) projects on the
    // meridian segment (r_b, 0) → (r_t, H): 0 at the bottom edge, 1 at the top.
    double meridian_fraction(double rho, double z) const {
        const double dr = top_radius - bottom_radius;
        return std::clamp(((rho - bottom_radius) * dr + z * height) / (dr * dr + height * height), 0.0, 1.0);
    }
};

using Wall = std::variant<PlaneWall, FrustumWall>;

struct WallPoint {
    Vec3 point;              // closest point of the wall surface to the particle centre
    Vec3 velocity;           // of that point
    bool behind = false;     // the centre is on the wrong side of a one-sided wall
};
WallPoint closest_wall_point(const Wall& wall, const Vec3& centre, double t);

// Whether the centre lies farther than `distance` (m, > 0) from the wall's surface at time t, and
// on its side: a bound the engine checks before closest_wall_point, for the particles no wall
// touches. Cheaper (no hypot, no closest point in 3D) and conservative: it answers true only
// where |centre − closest point| exceeds distance by a relative margin far above rounding, so
// skipping those particles changes no result.
inline bool surely_farther_than(const Wall& wall, const Vec3& centre, double t, double distance) {
    const double bound = distance * (1.0 + 1e-9);
    if (const auto* plane = std::get_if<PlaneWall>(&wall)) return (centre - plane->point).dot(plane->normal) > bound;
    // The frustum in the (ρ, z) half-plane of the centre: distance to its meridian segment.
    const FrustumWall& w = std::get<FrustumWall>(wall);
    const Vec3 rel = centre - (w.base_centre + w.offset(t));
    const double rho = std::sqrt(rel.x() * rel.x() + rel.y() * rel.y());
    const double s = w.meridian_fraction(rho, rel.z());
    const double across = rho - (w.bottom_radius + s * (w.top_radius - w.bottom_radius)), up = rel.z() - s * w.height;
    return across * across + up * up > bound * bound;
}

}  // namespace demscale::dem
