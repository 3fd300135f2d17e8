#include "slump/comparison.hpp"

#include <algorithm>
#include <cmath>

namespace demscale::slump {

double profile_height_at(const std::vector<ProfilePoint>& profile, double radius) {
    if (profile.empty() || radius > profile.back().radius) return 0;
    if (radius <= profile.front().radius) return profile.front().height;
    std::size_t i = 1;
    while (profile[i].radius < radius) ++i;
    const auto& a = profile[i - 1];
    const auto& b = profile[i];
    return a.height + (b.height - a.height) * (radius - a.radius) / (b.radius - a.radius);
}

std::vector<double> pile_shape(const PileMeasures& pile, const std::vector<double>& radii, double floor_level) {
    std::vector<ProfilePoint> occupied;  // empty bins dropped: interpolation bridges them
    for (const auto& q : pile.profile)
        if (q.height > 0) occupied.push_back({q.radius, q.height > floor_level ? q.height : 0.0});
    std::vector<double> h;
    for (double r : radii) h.push_back(occupied.empty() || r > occupied.back().radius ? 0.0 : profile_height_at(occupied, r));
    return h;
}

double fringe_level(const PileMeasures& a, const PileMeasures& b) { return 1.25 * std::max(a.foot, b.foot); }

std::vector<double> FineReference::shape(double floor_level) const {
    std::vector<double> mean(radii.size(), 0.0);
    for (const auto& p : piles) {
        const auto s = pile_shape(p, radii, floor_level);
        for (std::size_t i = 0; i < s.size(); ++i) mean[i] += s[i] / static_cast<double>(piles.size());
    }
    return mean;
}

double shape_distance(const std::vector<double>& a, const std::vector<double>& ref) {
    double d2 = 0, r2 = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) d2 += (a[i] - ref[i]) * (a[i] - ref[i]), r2 += ref[i] * ref[i];
    return r2 > 0 ? std::sqrt(d2 / r2) : 0;
}

FineReference fine_reference(const std::vector<const SlumpResult*>& fine, double radius, double extra_reach) {
    FineReference f;
    if (fine.empty()) return f;
    double reach = extra_reach;
    for (const auto* r : fine) reach = std::max(reach, r->final.spread_max);
    for (double x = radius; x <= 0.5 * reach + 2 * radius; x += 2 * radius) f.radii.push_back(x);
    const double n = static_cast<double>(fine.size());
    for (const auto* r : fine) {
        f.slump_over_height += r->slump() / r->initial_height / n;
        f.spread += r->final.spread / n;
        f.wall_s += r->wall_s / n;
        f.particle_steps += r->particle_steps() / n;
        f.piles.push_back(r->final);
    }
    return f;
}

RunComparison compare_to(const FineReference& f, const SlumpResult& run) {
    RunComparison c;
    c.slump_error = run.slump() / run.initial_height - f.slump_over_height;
    c.spread_error = (run.final.spread - f.spread) / f.spread;
    if (!f.piles.empty()) {
        const double level = fringe_level(f.piles.front(), run.final);
        c.profile_error = shape_distance(pile_shape(run.final, f.radii, level), f.shape(level));
    }
    c.wall_speedup = run.wall_s > 0 ? f.wall_s / run.wall_s : 0;
    const double work = run.particle_steps();
    c.work_speedup = work > 0 ? f.particle_steps / work : 0;
    return c;
}

}  // namespace demscale::slump
