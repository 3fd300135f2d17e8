#include "dem/walls.hpp"

#include <algorithm>
#include <cmath>

namespace demscale::dem {

namespace {

WallPoint closest(const PlaneWall& w, const Vec3& x, double) {
    const double d = (x - w.point).dot(w.normal);
    return {x - d * w.normal, Vec3::Zero(), !(d > 0)};
}

// The frustum's meridian is the segment (r_b, 0) → (r_t, H) in the (ρ, z) half-plane around its axis.
WallPoint closest(const FrustumWall& w, const Vec3& x, double t) {
    const Vec3 base = w.base_centre + w.offset(t);
    const Vec3 rel = x - base;
    const double rho = std::hypot(rel.x(), rel.y());
    const Vec3 radial = rho > 0 ? Vec3(rel.x() / rho, rel.y() / rho, 0) : Vec3::UnitX();
    const double s = w.meridian_fraction(rho, rel.z());
    const Vec3 point = base + (w.bottom_radius + s * (w.top_radius - w.bottom_radius)) * radial + s * w.height * Vec3::UnitZ();
    return {point, w.velocity_at(t), false};
}

}  // namespace

std::optional<double> wall_shift(const Wall& before, double t0, const Wall& now, double t1) {
    if (before.index() != now.index()) return std::nullopt;
    if (const auto* a = std::get_if<PlaneWall>(&before)) {
        const auto& b = std::get<PlaneWall>(now);
        if (a->point != b.point || a->normal != b.normal) return std::nullopt;
        return 0.0;
    }
    const auto& a = std::get<FrustumWall>(before);
    const auto& b = std::get<FrustumWall>(now);
    if (a.bottom_radius != b.bottom_radius || a.top_radius != b.top_radius || a.height != b.height) return std::nullopt;
    return ((b.base_centre + b.offset(t1)) - (a.base_centre + a.offset(t0))).norm();
}

WallPoint closest_wall_point(const Wall& wall, const Vec3& centre, double t) {
    return std::visit([&](const auto& w) { return closest(w, centre, t); }, wall);
}

}  // namespace demscale::dem
