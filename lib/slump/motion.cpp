#include "slump/motion.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace demscale::slump {

bool quantile_slower_than(const dem::Particles& p, std::size_t mobile, double speed, double quantile) {
    const double limit = speed * speed;
    const auto allowed = static_cast<std::size_t>(std::floor((1 - quantile) * static_cast<double>(mobile)));
    std::size_t fast = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!p.fixed[i] && !(p.velocity[i].squaredNorm() < limit) && ++fast > allowed) return false;
    return true;
}

namespace {
double quantile_of(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    const auto k = std::min(v.size() - 1, static_cast<std::size_t>(std::floor(q * static_cast<double>(v.size()))));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return v[k];
}
}  // namespace

MotionSummary summarize_motion(const dem::Particles& p, std::size_t count, double rest_speed) {
    MotionSummary m;
    if (count == 0) return m;
    std::vector<double> speed(count), spin(count), rho(count);
    double cx = 0, cy = 0;
    for (std::size_t i = 0; i < count; ++i) cx += p.position[i].x(), cy += p.position[i].y();
    cx /= static_cast<double>(count), cy /= static_cast<double>(count);
    for (std::size_t i = 0; i < count; ++i) {
        speed[i] = p.velocity[i].norm();
        spin[i] = p.angular_velocity[i].norm() * p.radius[i];
        rho[i] = std::hypot(p.position[i].x() - cx, p.position[i].y() - cy);
    }
    const double edge = quantile_of(rho, 0.95);
    for (std::size_t i = 0; i < count; ++i)
        if (speed[i] >= rest_speed) ++m.moving, m.moving_at_edge += rho[i] > edge;
    m.speed_max = *std::max_element(speed.begin(), speed.end());
    m.speed_p50 = quantile_of(speed, 0.5);
    m.speed_p99 = quantile_of(speed, 0.99);
    m.spin_p99 = quantile_of(spin, 0.99);
    return m;
}

}  // namespace demscale::slump
