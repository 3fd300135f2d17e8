// Walls particles collide with, using the same contact laws as particle pairs (R* = R, m* = m,
// the wall as a partner of radius 0 at the closest point of its surface).
//  PlaneWall   — infinite, one-sided: particles live on the side its normal points to.
//  FrustumWall — a thin open cone frustum (a cylinder when both radii are equal) around a vertical
//                axis, touched from either side; it can translate with a prescribed velocity during
//                a time window (the slump cone being lifted). Analytic, no mesh.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
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
        return std::clamp(meridian_projection(rho, z) / meridian_length2(), 0.0, 1.0);
    }
    // (ρ − r_b, z) · (r_t − r_b, H), m²: the fraction above times the meridian's squared length.
    double meridian_projection(double rho, double z) const {
        return (rho - bottom_radius) * (top_radius - bottom_radius) + z * height;
    }
    // (r_t − r_b)² + H², m².
    double meridian_length2() const {
        const double dr = top_radius - bottom_radius;
        return dr * dr + height * height;
    }
};

using Wall = std::variant<PlaneWall, FrustumWall>;

struct WallPoint {
    Vec3 point;              // closest point of the wall surface to the particle centre
    Vec3 velocity;           // of that point
    bool behind = false;     // the centre is on the wrong side of a one-sided wall
};
WallPoint closest_wall_point(const Wall& wall, const Vec3& centre, double t);

// How far a wall's surface moved from `before` at t0 to `now` at t1, m, when it only translated
// (a frustum's base and its lift); none when it changed shape or kind, or a plane moved at all.
std::optional<double> wall_shift(const Wall& before, double t0, const Wall& now, double t1);

// Whether centres lie farther than a distance from a wall's surface, and on its side: a bound the
// engine checks before closest_wall_point, for the particles no wall touches. Set up once per
// wall and instant (where the frustum stands, 1/|meridian|²), then asked for each particle: no
// hypot, no division, no closest point in 3D. Conservative: it answers true only where
// |centre − closest point| exceeds the distance by a relative margin far above rounding, so
// skipping those particles changes no result.
class WallBound {
public:
    WallBound(const Wall& wall, double t) {
        if (const auto* plane = std::get_if<PlaneWall>(&wall)) {
            plane_ = true, origin_ = plane->point, normal_ = plane->normal;
            return;
        }
        frustum_ = std::get<FrustumWall>(wall);
        origin_ = frustum_.base_centre + frustum_.offset(t);
        inverse_length2_ = 1.0 / frustum_.meridian_length2();
    }

    // distance: m, > 0.
    bool surely_farther_than(const Vec3& centre, double distance) const {
        const double bound = distance * (1.0 + 1e-9);
        if (plane_) return (centre - origin_).dot(normal_) > bound;
        // The frustum in the (ρ, z) half-plane of the centre: distance to its meridian segment. A
        // fraction s rounded differently from closest_wall_point's moves the segment point by
        // rounding only, far inside the margin.
        const Vec3 rel = centre - origin_;
        // Every point of the frustum lies in the slab 0 ≤ z ≤ H: a centre that far below or above
        // it needs no root (after the lift, the whole pile).
        if (rel.z() < -bound || rel.z() > frustum_.height + bound) return true;
        const double rho = std::sqrt(rel.x() * rel.x() + rel.y() * rel.y());
        const double s = std::clamp(frustum_.meridian_projection(rho, rel.z()) * inverse_length2_, 0.0, 1.0);
        const double across = rho - (frustum_.bottom_radius + s * (frustum_.top_radius - frustum_.bottom_radius));
        const double up = rel.z() - s * frustum_.height;
        return across * across + up * up > bound * bound;
    }

private:
    bool plane_ = false;
    Vec3 origin_ = Vec3::Zero();  // the plane's point, or the frustum's base centre at t, m
    Vec3 normal_ = Vec3::UnitZ();
    FrustumWall frustum_;
    double inverse_length2_ = 0;  // 1/((r_t − r_b)² + H²), 1/m²
};

}  // namespace demscale::dem
