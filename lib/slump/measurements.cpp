#include "slump/measurements.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace demscale::slump {

double lone_sphere_top(const SlumpScene& s) {
    return s.rough_floor ? (1 + 2 * std::sqrt(2.0 / 3.0)) * s.radius_m : 2 * s.radius_m;
}

PileMeasures measure_pile(const dem::Particles& p, double foot) {
    if (p.mobile_count() != p.size()) return measure_pile(p.mobile(), foot);
    PileMeasures m;
    m.foot = foot;
    if (p.size() == 0) return m;
    const double r = p.radius[0];
    double cx = 0, cy = 0;
    for (const auto& x : p.position) cx += x.x(), cy += x.y();
    cx /= static_cast<double>(p.size()), cy /= static_cast<double>(p.size());
    std::vector<double> rho;
    for (std::size_t i = 0; i < p.size(); ++i) {
        rho.push_back(std::hypot(p.position[i].x() - cx, p.position[i].y() - cy));
        m.height = std::max(m.height, p.position[i].z() + p.radius[i]);
    }
    std::vector<double> sorted = rho;
    const std::size_t k95 = std::min(sorted.size() - 1, static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(sorted.size()))) - 1);
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(k95), sorted.end());
    m.spread_d95 = 2 * (sorted[k95] + r);
    m.spread_max = 2 * (*std::max_element(rho.begin(), rho.end()) + r);

    const double bin = 2 * r;
    const std::size_t bins = static_cast<std::size_t>(m.spread_max / 2 / bin) + 1;
    m.profile.resize(bins);
    for (std::size_t b = 0; b < bins; ++b) m.profile[b] = {(static_cast<double>(b) + 0.5) * bin, 0.0};
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::size_t b = std::min(bins - 1, static_cast<std::size_t>(rho[i] / bin));
        m.profile[b].height = std::max(m.profile[b].height, p.position[i].z() + p.radius[i]);
    }
    // Flank: bins whose height above the foot lies between 20 % and 80 % of the pile's.
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    const double rise = m.height - foot;
    for (const auto& q : m.profile)
        if (q.height - foot > 0.2 * rise && q.height - foot < 0.8 * rise) {
            sx += q.radius, sy += q.height, sxx += q.radius * q.radius, sxy += q.radius * q.height, n += 1;
        }
    if (n >= 2 && n * sxx - sx * sx > 0) {
        const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        m.repose_angle_deg = std::atan(std::max(-slope, 0.0)) * 180.0 / std::numbers::pi;
    }
    return m;
}

}  // namespace demscale::slump
