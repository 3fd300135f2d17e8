#include "slump/comparison.hpp"

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

bool RunComparison::within(const Tolerances& t) const {
    return std::abs(slump_error) <= t.slump && std::abs(spread_error) <= t.spread && profile_error <= t.profile;
}

RunComparison compare_runs(const SlumpResult& fine, const SlumpResult& coarse) {
    auto relative = [](double coarse_value, double fine_value) { return (coarse_value - fine_value) / fine_value; };
    RunComparison c;
    c.slump_error = relative(coarse.slump(), fine.slump());
    c.spread_error = relative(coarse.final.spread_d95, fine.final.spread_d95);
    // Bins cover both piles: the fine bins, extended to the coarse pile's reach.
    double diff2 = 0, ref2 = 0;
    const double width = fine.final.profile.size() > 1 ? fine.final.profile[1].radius - fine.final.profile[0].radius : 0;
    const double reach = std::max(fine.final.profile.empty() ? 0 : fine.final.profile.back().radius,
                                  coarse.final.profile.empty() ? 0 : coarse.final.profile.back().radius);
    for (double r = fine.final.profile.empty() ? 0 : fine.final.profile.front().radius; width > 0 && r <= reach + 0.5 * width;
         r += width) {
        const double h = profile_height_at(fine.final.profile, r), hc = profile_height_at(coarse.final.profile, r);
        diff2 += (hc - h) * (hc - h);
        ref2 += h * h;
    }
    c.profile_error = ref2 > 0 ? std::sqrt(diff2 / ref2) : 0;
    c.wall_speedup = coarse.wall_s > 0 ? fine.wall_s / coarse.wall_s : 0;
    const double work_coarse = double(coarse.particles) * double(coarse.steps);
    c.work_speedup = work_coarse > 0 ? double(fine.particles) * double(fine.steps) / work_coarse : 0;
    return c;
}

}  // namespace demscale::slump
