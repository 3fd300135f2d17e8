// Walls particles collide with, using the same contact laws as particle pairs (R* = R, m* = m,
// the wall as a partner of radius 0 at the closest point of its surface).
//  PlaneWall   — infinite, one-sided: particles live on the side its normal points to.
//  FrustumWall — a thin open cone frustum (a cylinder when both radii are equal) around a vertical
//                axis, touched from either side; it can translate with a prescribed velocity during
//                a time window (the slump cone being lifted). Analytic, no mesh.
#pragma once

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

    Vec3 offset(double t) const;          // displacement of the wall at time t
    Vec3 velocity_at(double t) const;
};

using Wall = std::variant<PlaneWall, FrustumWall>;

struct WallPoint {
    Vec3 point;              // closest point of the wall surface to the particle centre
    Vec3 velocity;           // of that point
    bool behind = false;     // the centre is on the wrong side of a one-sided wall
};
WallPoint closest_wall_point(const Wall& wall, const Vec3& centre, double t);

}  // namespace demscale::dem
