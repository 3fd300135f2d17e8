#include "slump/measurements.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace demscale::slump {

double lone_sphere_top(const SlumpScene& s) {
    return s.rough_floor ? (1 + 2 * std::sqrt(2.0 / 3.0)) * s.radius_m : 2 * s.radius_m;
}

SurfaceGrid surface_grid(const SlumpScene& s) { return {s.top_diameter_m / 16, s.top_diameter_m / 2}; }

PileMeasures measure_pile(const dem::Particles& p, const SlumpScene& s) { return measure_pile(p, lone_sphere_top(s), surface_grid(s)); }

namespace {

// atan of minus the least-squares slope of the profile's points between 20 % and 80 % of `rise`
// above `base`; none with fewer than two such points.
std::optional<double> flank_angle_deg(const std::vector<ProfilePoint>& profile, double base, double rise) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    for (const auto& q : profile)
        if (q.height - base > 0.2 * rise && q.height - base < 0.8 * rise)
            sx += q.radius, sy += q.height, sxx += q.radius * q.radius, sxy += q.radius * q.height, n += 1;
    if (n < 2 || n * sxx - sx * sx <= 0) return std::nullopt;
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return std::atan(std::max(-slope, 0.0)) * 180.0 / std::numbers::pi;
}

}  // namespace

PileMeasures measure_pile(const dem::Particles& p, double foot, const SurfaceGrid& grid) {
    if (p.mobile_count() != p.size()) return measure_pile(p.mobile(), foot, grid);
    PileMeasures m;
    m.foot = foot;
    if (p.size() == 0) return m;
    const double r = p.radius[0];
    double cx = 0, cy = 0;
    for (const auto& x : p.position) cx += x.x(), cy += x.y();
    cx /= static_cast<double>(p.size()), cy /= static_cast<double>(p.size());

    const auto surface = pile_surface(p, cx, cy, grid);
    m.height = surface.height, m.spread = surface.spread, m.bulk_fraction = surface.bulk_fraction;
    for (std::size_t b = 0; b < surface.radii.size(); ++b) m.profile.push_back({surface.radii[b], surface.heights[b]});
    m.repose_angle_deg = flank_angle_deg(m.profile, 0, m.height);

    // The sphere-level measures.
    std::vector<double> rho;
    for (std::size_t i = 0; i < p.size(); ++i) {
        rho.push_back(std::hypot(p.position[i].x() - cx, p.position[i].y() - cy));
        m.height_top = std::max(m.height_top, p.position[i].z() + p.radius[i]);
    }
    std::vector<double> sorted = rho;
    const std::size_t k95 = std::min(sorted.size() - 1, static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(sorted.size()))) - 1);
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(k95), sorted.end());
    m.spread_d95 = 2 * (sorted[k95] + r);
    m.spread_max = 2 * (*std::max_element(rho.begin(), rho.end()) + r);
    const double bin = 2 * r;
    const std::size_t bins = static_cast<std::size_t>(m.spread_max / 2 / bin) + 1;
    m.profile_tops.resize(bins);
    for (std::size_t b = 0; b < bins; ++b) m.profile_tops[b] = {(static_cast<double>(b) + 0.5) * bin, 0.0};
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::size_t b = std::min(bins - 1, static_cast<std::size_t>(rho[i] / bin));
        m.profile_tops[b].height = std::max(m.profile_tops[b].height, p.position[i].z() + p.radius[i]);
    }
    return m;
}

}  // namespace demscale::slump
