#include "slump/ensemble_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/input_error.hpp"

namespace demscale::slump {

namespace {

std::vector<double> values(const std::vector<const SlumpResult*>& runs, double (*f)(const SlumpResult&)) {
    std::vector<double> v;
    for (const auto* r : runs) v.push_back(f(*r));
    return v;
}
double spread(const SlumpResult& r) { return r.final.spread; }

std::vector<double> mean_shape(const std::vector<std::vector<double>>& shapes, const std::vector<std::size_t>& pick) {
    std::vector<double> m(shapes.front().size(), 0.0);
    for (std::size_t i : pick)
        for (std::size_t j = 0; j < m.size(); ++j) m[j] += shapes[i][j] / static_cast<double>(pick.size());
    return m;
}

// Percentile bootstrap of the distance between the mean coarse and mean fine shapes.
stats::Interval bootstrap_profile(const std::vector<std::vector<double>>& fine, const std::vector<std::vector<double>>& coarse) {
    std::mt19937_64 rng(20261201);
    std::uniform_int_distribution<std::size_t> pick_f(0, fine.size() - 1), pick_c(0, coarse.size() - 1);
    constexpr int resamples = 2000;
    std::vector<double> d;
    std::vector<std::size_t> fi(fine.size()), ci(coarse.size());
    for (int b = 0; b < resamples; ++b) {
        for (auto& i : fi) i = pick_f(rng);
        for (auto& i : ci) i = pick_c(rng);
        d.push_back(shape_distance(mean_shape(coarse, ci), mean_shape(fine, fi)));
    }
    std::sort(d.begin(), d.end());
    return {d[static_cast<std::size_t>(0.025 * (resamples - 1))], d[static_cast<std::size_t>(0.975 * (resamples - 1))]};
}

std::vector<std::size_t> all_of(std::size_t n) {
    std::vector<std::size_t> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

}  // namespace

NoiseFloor noise_floor(const std::vector<const SlumpResult*>& fine, const FineReference& ref) {
    NoiseFloor n;
    n.slump_over_height = stats::summarize(values(fine, slump_over_height));
    n.spread = stats::summarize(values(fine, spread));
    std::vector<double> d;
    const double level = ref.piles.empty() ? 0 : fringe_level(ref.piles.front(), ref.piles.front());
    const auto mean = ref.shape(level);
    for (const auto* r : fine) d.push_back(shape_distance(pile_shape(r->final, ref.radii, level), mean));
    n.profile = stats::summarize(d);
    return n;
}

double slump_over_height(const SlumpResult& r) { return r.slump() / r.initial_height; }

EnsembleVerdict judge_ensemble(const std::vector<const SlumpResult*>& fine, const std::vector<const SlumpResult*>& coarse,
                               double sf, double exponent, const Tolerances& tol, double fine_radius, bool wet) {
    EnsembleVerdict v;
    v.sf = sf, v.exponent = exponent, v.fine_seeds = fine.size(), v.coarse_seeds = coarse.size();
    if (fine.empty() || coarse.empty()) return v;
    double reach = 0;
    for (const auto* r : coarse) reach = std::max(reach, r->final.spread_max);
    const auto ref = fine_reference(fine, fine_radius, reach);
    const auto noise = noise_floor(fine, ref);
    const bool too_few = fine.size() < 2 || coarse.size() < 2;

    auto criterion = [&](const std::string& measure, double estimate, stats::Interval interval, double tolerance) {
        Criterion c{measure, estimate, interval, tolerance, stats::equivalence_verdict(interval, tolerance),
                    stats::smallest_confirmable_tolerance(interval), ""};
        if (too_few) c.verdict = stats::Verdict::inconclusive, c.reason = "fewer than two seeds on a side: no interval";
        return c;
    };
    // Slump over H₀, absolute.
    const auto fs = values(fine, slump_over_height), cs = values(coarse, slump_over_height);
    auto slump = criterion("slump", stats::summarize(cs).mean - stats::summarize(fs).mean, stats::difference_interval(fs, cs), tol.slump);
    double fine_slump = 0;
    for (const auto* r : fine) fine_slump += r->slump() / static_cast<double>(fine.size());
    if (fine_slump < 2 * sf * fine_radius) {
        slump.verdict = stats::Verdict::inconclusive;
        slump.reason = "the fine reference slumps " + format_short(fine_slump * 1e3, 3) + " mm, less than one coarse diameter (" +
                       format_short(2 * sf * fine_radius * 1e3, 3) + " mm): this scene cannot tell exponents apart by slump";
    }
    // Spread (diameter at half height), relative to the fine mean.
    const auto fd = values(fine, spread), cd = values(coarse, spread);
    const double mean_fd = stats::summarize(fd).mean;
    const auto dd = stats::difference_interval(fd, cd);
    auto spread = criterion("spread", (stats::summarize(cd).mean - mean_fd) / mean_fd, {dd.low / mean_fd, dd.high / mean_fd}, tol.spread);
    // Profile: distance of the mean shapes, bootstrapped.
    std::vector<std::vector<double>> fsh, csh;
    const double level = fringe_level(fine.front()->final, coarse.front()->final);
    for (const auto* r : fine) fsh.push_back(pile_shape(r->final, ref.radii, level));
    for (const auto* r : coarse) csh.push_back(pile_shape(r->final, ref.radii, level));
    const double distance = shape_distance(mean_shape(csh, all_of(csh.size())), mean_shape(fsh, all_of(fsh.size())));
    auto profile = criterion("profile", distance, too_few ? stats::Interval{distance, distance} : bootstrap_profile(fsh, csh), tol.profile);

    v.criteria = {slump, spread, profile};
    v.overall = stats::combine({slump.verdict, spread.verdict, profile.verdict});
    auto below_noise = [&](const char* what, double tolerance, double scatter) {
        if (fine.size() >= 2 && tolerance < scatter)
            v.warnings.push_back(std::string(what) + " tolerance " + format_short(100 * tolerance, 3) + " % is below the fine ensemble's own spread (" +
                                 format_short(100 * scatter, 3) + " %)");
    };
    below_noise("slump", tol.slump, noise.slump_over_height.sd);
    below_noise("spread", tol.spread, noise.spread.sd / noise.spread.mean);
    below_noise("profile", tol.profile, noise.profile.mean);
    if (!wet) v.warnings.push_back("dry scene: k scales only the surface tension, which it does not use; the exponent has no effect");
    return v;
}

}  // namespace demscale::slump
