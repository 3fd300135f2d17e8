#include "slump/response_study.hpp"

#include "slump/coarse_grain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/input_error.hpp"

namespace demscale::slump {

std::string ResponseEnsemble::unusable() const {
    for (const auto& r : measured)
        if (!r.unusable.empty()) return "seed " + std::to_string(r.seed) + ": " + r.unusable;
    return "";
}

bool ResponseEnsemble::all_at_rest() const {
    return std::all_of(measured.begin(), measured.end(), [](const RunRow& r) { return r.at_rest; });
}

namespace {

// The seeds' runs of one level: the scene at surface tension gamma (N/m; ignored dry).
ResponseEnsemble ensemble(const SlumpScene& fine, double sf, double gamma, int seeds) {
    ResponseEnsemble e;
    e.sf = sf;
    e.gamma = fine.wet ? gamma : 0.0;
    SlumpScene level = fine;
    level.liquid.surface_tension_n_per_m = gamma;
    StudyRun run;
    run.grain = {sf, 0, {}};  // γ is set here already: k = 0 leaves it
    run.scene = sf == 1 ? level : coarse_grained(level, run.grain);
    const std::string where = sf == 1 ? "fine" : "S_f = " + format_short(sf, 3);
    run.label = fine.wet ? where + (sf == 1 ? ", γ = " : ", γ̄ = ") + format_short(gamma, 4) + " N/m" : where + ", dry";
    for (int i = 0; i < seeds; ++i) {
        e.runs.push_back(run);
        e.runs.back().scene.seed = fine.seed + static_cast<unsigned>(i);
    }
    return e;
}

void measure(ResponseEnsemble& e, double bottom_diameter) {
    e.measured.clear();
    for (const auto& r : e.runs) e.measured.push_back(run_row(r, bottom_diameter));
}

void summarize_ensemble(ResponseEnsemble& e) {
    if (!e.unusable().empty()) return;  // no column to measure
    std::vector<double> s, d;
    for (const auto& r : e.measured) s.push_back(r.slump_over_height), d.push_back(r.spread_over_d0);
    e.slump_over_height = stats::summarize(s);
    e.spread_over_diameter = stats::summarize(d);
}

// An ensemble's slump over fill height, one value per seed with its seed.
stats::ResponseLevel level_of(const ResponseEnsemble& e) {
    stats::ResponseLevel l;
    l.x = e.gamma > 0 ? std::log(e.gamma) : 0.0;
    for (const auto& r : e.measured) l.y.push_back(r.slump_over_height), l.seed.push_back(r.seed);
    return l;
}

stats::ResponseCurve curve(double sf, const std::vector<ResponseEnsemble>& levels) {
    stats::ResponseCurve c;
    c.sf = sf;
    for (const auto& e : levels) {
        if (!e.unusable().empty()) continue;  // a level whose fills the cone could not hold is no point of the curve
        c.levels.push_back(level_of(e));
    }
    return c;
}

std::vector<const SlumpResult*> results(const ResponseEnsemble& e) {
    std::vector<const SlumpResult*> r;
    for (const auto& run : e.runs) r.push_back(&run.result);
    return r;
}

DryBaseline baseline(double sf, const ResponseEnsemble& fine, const ResponseEnsemble& coarse, const SlumpScene& scene) {
    const auto f = results(fine), c = results(coarse);
    DryBaseline b;
    b.sf = sf;
    b.criteria = judge_ensemble(f, c, sf, 0, scene.tolerances, scene.radius_m, false).criteria;
    double reach = 0;
    for (const auto* r : f) reach = std::max(reach, r->final.spread_max);
    b.noise = noise_floor(f, fine_reference(f, scene.radius_m, reach));
    return b;
}

}  // namespace

std::vector<double> log_spaced_factors(double lo, double hi, int levels, const std::string& range_field,
                                       const std::string& levels_field) {
    if (!(lo > 0) || !(hi > lo) || !std::isfinite(hi))
        throw InputError(range_field, format_number(lo) + "," + format_number(hi),
                         "two surface tension factors LO,HI with 0 < LO < HI (e.g. 0.25,4)");
    if (levels < 3 || levels > 12) throw InputError(levels_field, std::to_string(levels), "3 to 12");
    std::vector<double> f;
    for (int i = 0; i < levels; ++i) f.push_back(std::stod(format_short(lo * std::pow(hi / lo, double(i) / (levels - 1)), 12)));
    return f;
}

void validate_response_plan(const ResponsePlan& plan) {
    if (plan.seeds < 2 || plan.seeds > 64) throw InputError("--seeds", std::to_string(plan.seeds), "2 to 64 (runs per level)");
    if (plan.scale_factors.empty()) throw InputError("--sf", "(none)", "at least one scale factor > 1");
    for (double sf : plan.scale_factors)
        if (!(sf > 1)) throw InputError("--sf", format_number(sf), "> 1 (the fine scene is S_f = 1)");
    for (double sf : plan.scale_factors)  // the cone, not the exponent, would shift a geometry-limited curve
        if (const auto why = geometry_limits(plan.fine, sf); !why.empty())
            throw InputError("--sf", format_number(sf), "an S_f this scene's cone does not limit (geometry-limited: " + why.front() + ")");
    if (plan.fine.wet) {
        if (plan.factors.size() < 3) throw InputError("--levels", std::to_string(plan.factors.size()), "3 to 12");
        for (std::size_t i = 0; i < plan.factors.size(); ++i)
            if (!(plan.factors[i] > 0) || (i > 0 && !(plan.factors[i] > plan.factors[i - 1])))
                throw InputError("--range", format_number(plan.factors[i]), "positive surface tension factors, ascending");
    }
    require_in_open_interval(plan.offset_exponent, -20, 20, "--offset");
    if (plan.batch.jobs < 1) throw InputError("--jobs", std::to_string(plan.batch.jobs), ">= 1");
    if (plan.batch.threads_per_job < 1) throw InputError("--threads", std::to_string(plan.batch.threads_per_job), ">= 1");
    check_slump_time_step(plan.fine, plan.batch.force_dt);
    for (double sf : plan.scale_factors) check_slump_time_step(coarse_grained(plan.fine, {sf, 0, {}}), plan.batch.force_dt);
}

const stats::SplitLevel* split_of(const ResponseStudy& study, const ResponseEnsemble& e) {
    for (const auto& s : study.split)
        if (s.sf == e.sf && s.x == std::log(e.gamma)) return &s;  // x as curve() computes it
    return nullptr;
}

std::vector<StudyRun*> ResponseStudy::all_runs() {
    std::vector<StudyRun*> all;
    for (auto& e : fine)
        for (auto& r : e.runs) all.push_back(&r);
    for (auto& levels : coarse)
        for (auto& e : levels)
            for (auto& r : e.runs) all.push_back(&r);
    for (auto& e : dry_control)
        for (auto& r : e.runs) all.push_back(&r);
    return all;
}

ResponseStudy plan_response_runs(const ResponsePlan& plan) {
    validate_response_plan(plan);
    ResponseStudy study;
    study.wet = plan.fine.wet;
    const double gamma = plan.fine.liquid.surface_tension_n_per_m;
    const std::vector<double> factors = study.wet ? plan.factors : std::vector<double>{1.0};
    for (double f : factors) study.fine.push_back(ensemble(plan.fine, 1, f * gamma, plan.seeds));
    for (double sf : plan.scale_factors) {
        study.coarse.emplace_back();
        for (double f : factors) study.coarse.back().push_back(ensemble(plan.fine, sf, f * gamma * std::pow(sf, plan.offset_exponent), plan.seeds));
    }
    if (study.wet && plan.baseline == Baseline::dry) {
        SlumpScene dry = plan.fine;
        dry.wet = dry.wet_walls = false;
        study.dry_control.push_back(ensemble(dry, 1, 0, plan.seeds));
        for (double sf : plan.scale_factors) study.dry_control.push_back(ensemble(dry, sf, 0, plan.seeds));
        for (auto& e : study.dry_control)
            for (auto& r : e.runs) r.label += " control";
    }
    return study;
}

namespace {

// Everything after the runs: summaries, curves, k (wet) or the dry control's differences (dry).
void judge_response(ResponseStudy& study, const ResponsePlan& plan) {
    for (auto& e : study.fine) summarize_ensemble(e);
    for (auto& levels : study.coarse)
        for (auto& e : levels) summarize_ensemble(e);
    for (auto& e : study.dry_control) summarize_ensemble(e);
    for (const auto& e : study.dry_control)
        if (const auto why = e.unusable(); !why.empty())
            throw std::runtime_error("the dry control at S_f = " + format_short(e.sf, 3) + ", " + why);
    if (!study.wet) {
        for (std::size_t s = 0; s < plan.scale_factors.size(); ++s)
            study.baselines.push_back(baseline(plan.scale_factors[s], study.fine.front(), study.coarse[s].front(), plan.fine));
        return;
    }
    study.fine_curve = curve(1, study.fine);
    if (study.fine_curve.levels.size() < 2)
        throw std::runtime_error("fewer than two fine levels whose fills the cone could hold: no fine response curve");
    for (std::size_t s = 0; s < plan.scale_factors.size(); ++s) {
        study.coarse_curves.push_back(curve(plan.scale_factors[s], study.coarse[s]));
        if (study.coarse_curves.back().levels.empty())
            throw std::runtime_error("S_f = " + format_short(plan.scale_factors[s], 3) + ": no level's fills could be used (" +
                                     study.coarse[s].front().unusable() + ")");
    }
    if (study.has_control()) {
        study.raw_estimates = stats::estimate_exponent(study.fine_curve, study.coarse_curves, plan.search);
        study.raw_fits = stats::fit_transition(study.fine_curve, study.coarse_curves, plan.transition);
        study.fine_curve.control = level_of(study.dry_control.front());
        for (std::size_t s = 0; s < study.coarse_curves.size(); ++s) study.coarse_curves[s].control = level_of(study.dry_control[s + 1]);
    }
    study.estimates = stats::estimate_exponent(study.fine_curve, study.coarse_curves, plan.search);
    study.fits = stats::fit_transition(study.fine_curve, study.coarse_curves, plan.transition);
    study.stands_below = plan.transition.stands_below;
    study.split = stats::split_levels(study.fine_curve, study.coarse_curves);
    study.fine_range = {INFINITY, -INFINITY};
    for (const auto& l : study.fine_curve.levels) study.fine_range = {std::min(study.fine_range.low, l.x), std::max(study.fine_range.high, l.x)};
    study.passing = stats::passing_ranges(study.fits, plan.scale_factors, std::log(plan.fine.liquid.surface_tension_n_per_m),
                                          plan.fine.tolerances.slump, study.fine_range);
}

}  // namespace

ResponseStudy run_response_study(const ResponsePlan& plan, const std::function<void(const std::string&)>& log) {
    const auto start = std::chrono::steady_clock::now();
    ResponseStudy study = plan_response_runs(plan);
    const auto all = study.all_runs();
    BatchOptions batch = plan.batch;
    batch.reference_radius_m = plan.fine.radius_m;
    run_batch(all, batch, log);
    study.second_look = second_look(all);
    const double d0 = plan.fine.bottom_diameter_m;
    for (auto& e : study.fine) measure(e, d0);
    for (auto& levels : study.coarse)
        for (auto& e : levels) measure(e, d0);
    for (auto& e : study.dry_control) measure(e, d0);
    judge_response(study, plan);
    study.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return study;
}

std::vector<RunRow> response_runs(const ResponseStudy& study) {
    std::vector<RunRow> rows;
    auto add = [&](const ResponseEnsemble& e) { rows.insert(rows.end(), e.measured.begin(), e.measured.end()); };
    for (const auto& e : study.fine) add(e);
    for (const auto& levels : study.coarse)
        for (const auto& e : levels) add(e);
    for (const auto& e : study.dry_control) add(e);
    return rows;
}

ResponseStudy response_study_from_runs(const std::vector<RunRow>& rows, ResponsePlan plan, const std::string& source) {
    const auto start = std::chrono::steady_clock::now();
    if (!plan.fine.wet) throw InputError("--runs", source, "runs of a wet scene (a dry scene's estimate compares whole piles: run it)");
    // Ensembles in the order of first appearance, levels sorted by γ within each S_f.
    std::vector<double> sfs;
    for (const auto& r : rows)
        if (r.sf > 1 && std::find(sfs.begin(), sfs.end(), r.sf) == sfs.end()) sfs.push_back(r.sf);
    std::sort(sfs.begin(), sfs.end());
    ResponseStudy study;
    study.wet = true;
    study.coarse.resize(sfs.size());
    auto place = [&](std::vector<ResponseEnsemble>& list, const RunRow& r) {
        auto it = std::find_if(list.begin(), list.end(), [&](const ResponseEnsemble& e) { return e.gamma == r.gamma && e.sf == r.sf; });
        if (it == list.end()) {
            list.push_back({});
            it = list.end() - 1;
            it->sf = r.sf, it->gamma = r.gamma;
        }
        it->measured.push_back(r);
    };
    std::vector<ResponseEnsemble> dry;
    for (const auto& r : rows) {
        if (r.gamma == 0) place(dry, r);
        else if (r.sf == 1) place(study.fine, r);
        else place(study.coarse[static_cast<std::size_t>(std::find(sfs.begin(), sfs.end(), r.sf) - sfs.begin())], r);
    }
    auto by_gamma = [](const ResponseEnsemble& a, const ResponseEnsemble& b) { return a.gamma < b.gamma; };
    std::sort(study.fine.begin(), study.fine.end(), by_gamma);
    for (auto& levels : study.coarse) std::sort(levels.begin(), levels.end(), by_gamma);
    if (study.fine.size() < 2) throw InputError("--runs", source, "runs at two or more fine (sf = 1) surface tensions");
    if (sfs.empty()) throw InputError("--runs", source, "runs of at least one coarse scale factor (sf > 1) with liquid");
    if (!dry.empty()) {  // the dry control: fine, then each S_f, or none at all
        std::sort(dry.begin(), dry.end(), [](const auto& a, const auto& b) { return a.sf < b.sf; });
        if (dry.size() != sfs.size() + 1 || dry.front().sf != 1)
            throw InputError("--runs", source, "dry control rows (gamma 0) for the fine scene and every coarse S_f, or for none");
        study.dry_control = std::move(dry);
    }
    plan.scale_factors = sfs;
    judge_response(study, plan);
    study.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return study;
}

}  // namespace demscale::slump
