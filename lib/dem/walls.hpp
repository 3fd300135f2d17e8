// Walls particles collide with, using the same contact laws (R* = R, m* = m).
#pragma once

#include "dem/particles.hpp"

namespace demscale::dem {

// Infinite plane through `point` with unit `normal` pointing into the domain.
struct PlaneWall {
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ();

    // Signed distance of a sphere centre to the plane (m) and the unit normal at the contact.
    double distance(const Vec3& x) const { return (x - point).dot(normal); }
};

}  // namespace demscale::dem
