#include "slump/ensemble_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "core/input_error.hpp"
#include "stats/shape_distance.hpp"

namespace demscale::slump {

namespace {

std::vector<double> values(const std::vector<const SlumpResult*>& runs, double (*f)(const SlumpResult&)) {
    std::vector<double> v;
    for (const auto* r : runs) v.push_back(f(*r));
    return v;
}
double spread(const SlumpResult& r) { return r.final.spread; }

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

Criterion difference_criterion(const std::string& measure, const std::vector<double>& fine, const std::vector<double>& coarse,
                               double scale, double tolerance) {
    const auto d = stats::difference_interval(fine, coarse);
    const stats::Interval interval{d.low / scale, d.high / scale};
    Criterion c{measure, (stats::summarize(coarse).mean - stats::summarize(fine).mean) / scale, interval, tolerance,
                stats::equivalence_verdict(interval, tolerance), stats::smallest_confirmable_tolerance(interval), ""};
    if (fine.size() < 2 || coarse.size() < 2) c.verdict = stats::Verdict::inconclusive, c.reason = "fewer than two seeds on a side: no interval";
    return c;
}

std::size_t family_size(const std::vector<EnsembleVerdict>& deciding) {
    std::size_t m = 0;
    for (const auto& e : deciding)
        if (e.unusable.empty()) m += e.criteria.size();
    return m;
}

stats::Verdict family_verdict(const std::vector<EnsembleVerdict>& deciding) {
    std::vector<stats::Verdict> v;
    for (const auto& e : deciding)
        if (e.unusable.empty()) v.push_back(e.overall);
    if (v.empty()) return stats::Verdict::inconclusive;
    const stats::Verdict worst = stats::combine(v);
    if (worst != stats::Verdict::fail) return worst;
    const std::size_t m = family_size(deciding);
    for (const auto& e : deciding)
        if (e.unusable.empty())
            for (const auto& c : e.criteria)
                if (c.reason.empty() && stats::fails_in_family(c.estimate, c.interval, c.tolerance, m)) return stats::Verdict::fail;
    return stats::Verdict::inconclusive;  // every FAIL is one a family of m tests draws by chance too often
}

EnsembleVerdict judge_ensemble(const std::vector<const SlumpResult*>& fine, const std::vector<const SlumpResult*>& coarse,
                               double sf, double exponent, const Tolerances& tol, double fine_radius, bool wet,
                               const DryControl* control) {
    EnsembleVerdict v;
    v.sf = sf, v.exponent = exponent, v.fine_seeds = fine.size(), v.coarse_seeds = coarse.size();
    if (fine.empty() || coarse.empty()) return v;
    if (control && (control->fine.size() != fine.size() || control->coarse.size() != coarse.size()))
        throw std::invalid_argument("judge_ensemble: the dry control must hold the same seeds as the wet ensembles");
    double reach = 0;
    for (const auto* r : coarse) reach = std::max(reach, r->final.spread_max);
    if (control)
        for (const auto& side : {control->fine, control->coarse})
            for (const auto* r : side) reach = std::max(reach, r->final.spread_max);
    const auto ref = fine_reference(fine, fine_radius, reach);
    const auto noise = noise_floor(fine, ref);
    const bool too_few = fine.size() < 2 || coarse.size() < 2;

    auto criterion = [&](const std::string& measure, double estimate, stats::Interval interval, double tolerance) {
        Criterion c{measure, estimate, interval, tolerance, stats::equivalence_verdict(interval, tolerance),
                    stats::smallest_confirmable_tolerance(interval), ""};
        if (too_few) c.verdict = stats::Verdict::inconclusive, c.reason = "fewer than two seeds on a side: no interval";
        return c;
    };
    // Each seed's value, less its dry twin's with a control.
    auto seedwise = [&](const std::vector<const SlumpResult*>& runs, const std::vector<const SlumpResult*>* dry,
                        double (*f)(const SlumpResult&)) {
        auto x = values(runs, f);
        if (dry)
            for (std::size_t i = 0; i < x.size(); ++i) x[i] -= f(*(*dry)[i]);
        return x;
    };
    const auto* dry_fine = control ? &control->fine : nullptr;
    const auto* dry_coarse = control ? &control->coarse : nullptr;
    // Slump over H₀, absolute.
    auto slump = difference_criterion("slump", seedwise(fine, dry_fine, slump_over_height), seedwise(coarse, dry_coarse, slump_over_height),
                                      1, tol.slump);
    double fine_slump = 0;
    for (const auto* r : fine) fine_slump += r->slump() / static_cast<double>(fine.size());
    if (fine_slump < 2 * sf * fine_radius) {
        slump.verdict = stats::Verdict::inconclusive;
        slump.reason = "the fine reference slumps " + format_short(fine_slump * 1e3, 3) + " mm, less than one coarse diameter (" +
                       format_short(2 * sf * fine_radius * 1e3, 3) + " mm): this scene cannot tell exponents apart by slump";
    }
    // Spread (diameter at half height), relative to the fine mean.
    const auto fd = seedwise(fine, dry_fine, spread), cd = seedwise(coarse, dry_coarse, spread);
    const double mean_fd = stats::summarize(values(fine, spread)).mean;
    auto spread = difference_criterion("spread", fd, cd, mean_fd, tol.spread);
    // Profile: distance of the mean shapes, bootstrapped.
    const double level = fringe_level(fine.front()->final, coarse.front()->final);
    auto shapes_of = [&](const std::vector<const SlumpResult*>& runs, const std::vector<const SlumpResult*>* dry) {
        std::vector<std::vector<double>> s;
        for (std::size_t i = 0; i < runs.size(); ++i) {
            s.push_back(pile_shape(runs[i]->final, ref.radii, level));
            if (dry) {
                const auto d = pile_shape((*dry)[i]->final, ref.radii, level);
                for (std::size_t j = 0; j < d.size(); ++j) s.back()[j] -= d[j];
            }
        }
        return s;
    };
    const stats::ShapeEnsembles shapes{shapes_of(coarse, dry_coarse), shapes_of(fine, dry_fine), shapes_of(fine, nullptr)};
    // With one seed on a side there is no noise to remove: the plain distance, INCONCLUSIVE anyway.
    auto plain = [&] {
        const double d = stats::shape_distance_of(shapes, all_of(coarse.size()), all_of(fine.size()), false);
        return stats::ShapeDistance{d, d, {d, d}};
    };
    const auto distance = too_few ? plain() : stats::measure_shape_distance(shapes);
    auto profile = criterion("profile", distance.distance, distance.ci, tol.profile);

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
