#include "slump/runs_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/input_error.hpp"

namespace demscale::slump {

namespace {

bool same(double a, double b, double relative) { return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)); }

// The runs at one S_f and one γ (0: the dry control), by seed.
std::map<long, const RunRow*> ensemble(const std::vector<RunRow>& rows, double sf, double gamma) {
    std::map<long, const RunRow*> e;
    for (const auto& r : rows)
        if (same(r.sf, sf, 1e-9) && (gamma == 0 ? r.gamma == 0 : same(r.gamma, gamma, 1e-3))) e.emplace(r.seed, &r);
    return e;
}

std::string unusable_of(const std::map<long, const RunRow*>& e) {
    for (const auto& [seed, r] : e)
        if (!r->unusable.empty()) return "seed " + std::to_string(seed) + ": " + r->unusable;
    return "";
}

// Slump over height and spread over d0 of each seed, less its dry twin's when dry is given.
std::pair<std::vector<double>, std::vector<double>> measures(const std::map<long, const RunRow*>& wet,
                                                             const std::map<long, const RunRow*>* dry) {
    std::vector<double> slump, spread;
    for (const auto& [seed, r] : wet) {
        const RunRow* twin = dry ? dry->at(seed) : nullptr;
        slump.push_back(r->slump_over_height - (twin ? twin->slump_over_height : 0));
        spread.push_back(r->spread_over_d0 - (twin ? twin->spread_over_d0 : 0));
    }
    return {slump, spread};
}

double mean_spread(const std::map<long, const RunRow*>& e) {
    double m = 0;
    for (const auto& [seed, r] : e) m += r->spread_over_d0 / static_cast<double>(e.size());
    return m;
}

EnsembleVerdict judge(const std::map<long, const RunRow*>& fine, const std::map<long, const RunRow*>& coarse,
                      const std::map<long, const RunRow*>* dry_fine, const std::map<long, const RunRow*>* dry_coarse, double sf,
                      double exponent, const Tolerances& tol) {
    EnsembleVerdict v;
    v.sf = sf, v.exponent = exponent, v.fine_seeds = fine.size(), v.coarse_seeds = coarse.size();
    for (const auto* e : {&fine, &coarse, dry_fine, dry_coarse})
        if (e && v.unusable.empty()) v.unusable = unusable_of(*e);
    if (!v.unusable.empty()) return v;
    const auto [fs, fd] = measures(fine, dry_fine);
    const auto [cs, cd] = measures(coarse, dry_coarse);
    v.criteria = {difference_criterion("slump", fs, cs, 1, tol.slump), difference_criterion("spread", fd, cd, mean_spread(fine), tol.spread)};
    v.overall = stats::combine({v.criteria[0].verdict, v.criteria[1].verdict});
    v.warnings.push_back("a runs file holds no profiles: judged on slump and spread only");
    return v;
}

}  // namespace

RunsVerdicts judge_runs(const std::vector<RunRow>& rows, const std::string& source, double scene_gamma, double exponent,
                        std::vector<double> scale_factors, const Tolerances& tolerances, Baseline baseline) {
    if (scale_factors.empty())
        for (const auto& r : rows)
            if (r.sf > 1 && std::none_of(scale_factors.begin(), scale_factors.end(), [&](double s) { return same(s, r.sf, 1e-9); }))
                scale_factors.push_back(r.sf);
    if (scale_factors.empty()) throw InputError("--runs", source, "rows with S_f > 1 (coarse runs) beside the fine ones (S_f 1)");
    const auto fine = ensemble(rows, 1, scene_gamma);
    if (fine.empty())
        throw InputError("--runs", source, "fine runs (S_f 1) at the scene's surface tension " + format_short(scene_gamma, 6) + " N/m");
    const bool dry = baseline == Baseline::dry &&
                     std::any_of(rows.begin(), rows.end(), [](const RunRow& r) { return r.gamma == 0; });
    const auto dry_fine = dry ? ensemble(rows, 1, 0) : std::map<long, const RunRow*>{};
    // Every wet seed needs its dry twin: a control of other seeds would not remove the same pile's offset.
    auto check_twins = [&](const std::map<long, const RunRow*>& wet, const std::map<long, const RunRow*>& twins, double sf) {
        for (const auto& [seed, r] : wet)
            if (!twins.count(seed))
                throw InputError("--runs", source, "a dry run (gamma 0) at S_f " + format_short(sf, 6) + " for seed " + std::to_string(seed) +
                                                       ", or --baseline none (the file has a dry control, so each wet seed needs its twin)");
    };
    if (dry) check_twins(fine, dry_fine, 1);
    RunsVerdicts out;
    out.tolerances = tolerances;
    for (double sf : scale_factors) {
        const double gamma = scene_gamma * std::pow(sf, exponent);
        const auto coarse = ensemble(rows, sf, gamma);
        if (coarse.empty())
            throw InputError("--runs", source, "coarse runs at S_f " + format_short(sf, 6) + " with gamma-bar = gamma S_f^k = " +
                                                   format_short(gamma, 6) + " N/m (k = " + format_short(exponent, 6) + ")");
        out.raw.push_back(judge(fine, coarse, nullptr, nullptr, sf, exponent, tolerances));
        if (!dry) continue;
        const auto dry_coarse = ensemble(rows, sf, 0);
        check_twins(coarse, dry_coarse, sf);
        out.corrected.push_back(judge(fine, coarse, &dry_fine, &dry_coarse, sf, exponent, tolerances));
        out.controls.push_back(judge(dry_fine, dry_coarse, nullptr, nullptr, sf, exponent, tolerances));
    }
    return out;
}

}  // namespace demscale::slump
