#include "slump/study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/input_error.hpp"

namespace demscale::slump {

std::size_t Study::family_size() const { return slump::family_size(deciding()); }

stats::Verdict Study::overall() const { return family_verdict(deciding()); }

std::vector<double> Study::judged_scale_factors() const {
    std::vector<double> sfs;
    for (const auto& v : deciding())
        if (v.unusable.empty() && std::find(sfs.begin(), sfs.end(), v.sf) == sfs.end()) sfs.push_back(v.sf);
    return sfs;
}

std::vector<const SlumpResult*> Study::fine_ensemble() const {
    std::vector<const SlumpResult*> f = {&reference.result};
    for (const auto& r : replicas) f.push_back(&r.result);
    return f;
}

std::vector<const StudyRun*> Study::coarse_runs(std::size_t i) const {
    std::vector<const StudyRun*> c = {&runs.at(i)};
    const std::size_t others = coarse_seeds.size() / runs.size();
    for (std::size_t j = 0; j < others; ++j) c.push_back(&coarse_seeds.at(i * others + j));
    return c;
}

std::vector<const SlumpResult*> Study::coarse_ensemble(std::size_t i) const {
    std::vector<const SlumpResult*> c;
    for (const auto* r : coarse_runs(i)) c.push_back(&r->result);
    return c;
}

std::vector<const StudyRun*> Study::fine_runs() const {
    std::vector<const StudyRun*> f = {&reference};
    for (const auto& r : replicas) f.push_back(&r);
    for (const auto& r : dry_fine) f.push_back(&r);
    return f;
}

std::string Study::unusable(std::size_t i) const {
    auto ensemble = coarse_runs(i);
    if (has_control())
        for (const auto& r : dry_coarse.at(i)) ensemble.push_back(&r);
    std::size_t n = 0;
    std::string first;
    for (const auto* r : ensemble)
        if (!r->unusable.empty() && n++ == 0)
            first = std::string(r->scene.wet ? "" : "dry control, ") + "seed " + std::to_string(r->scene.seed) + ": " + r->unusable;
    if (n == 0) return "";
    return std::to_string(n) + " of " + std::to_string(ensemble.size()) + " fills unusable (" + first + ")";
}

std::vector<const SlumpResult*> Study::dry_fine_ensemble() const {
    std::vector<const SlumpResult*> f;
    for (const auto& r : dry_fine) f.push_back(&r.result);
    return f;
}

std::vector<const SlumpResult*> Study::dry_coarse_ensemble(std::size_t i) const {
    std::vector<const SlumpResult*> c;
    for (const auto& r : dry_coarse.at(i)) c.push_back(&r.result);
    return c;
}

const EnsembleVerdict& Study::best_at(double sf) const {
    const EnsembleVerdict* best = nullptr;
    for (const auto& v : deciding())
        if (v.sf == sf && v.unusable.empty() && (!best || v.criteria.at(2).estimate < best->criteria.at(2).estimate)) best = &v;
    if (!best) throw InputError("--sf", format_number(sf), "one of the study's scale factors");
    return *best;
}

std::vector<double> Study::not_told_apart_from_best(double sf) const {
    const auto& best = best_at(sf);
    std::vector<double> ks;
    for (const auto& v : deciding())
        if (&v != &best && v.sf == sf && v.unusable.empty() && v.criteria.at(2).interval.low <= best.criteria.at(2).interval.high)
            ks.push_back(v.exponent);
    return ks;
}

void validate_plan(const StudyPlan& plan) {
    if (plan.jobs < 1) throw InputError("--jobs", std::to_string(plan.jobs), ">= 1");
    if (plan.threads_per_job < 1) throw InputError("--threads", std::to_string(plan.threads_per_job), ">= 1");
    if (plan.exponents.empty()) throw InputError("--exponents", "(none)", "at least one exponent");
    if (plan.seeds < 1 || plan.seeds > 64) throw InputError("--seeds", std::to_string(plan.seeds), "1 to 64 (runs per ensemble)");
    check_slump_time_step(plan.fine, plan.force_dt);
    for (double k : plan.exponents)
        for (double sf : plan.scale_factors) check_slump_time_step(coarse_grained(plan.fine, {sf, k, plan.scaled}), plan.force_dt);
}

std::vector<const StudyRun*> Study::all_runs() const {
    const auto all = const_cast<Study*>(this)->all_runs();  // the same list, read only
    return {all.begin(), all.end()};
}

std::vector<StudyRun*> Study::all_runs() {
    std::vector<StudyRun*> all = {&reference};
    for (auto& r : replicas) all.push_back(&r);
    for (auto& r : runs) all.push_back(&r);
    for (auto& r : coarse_seeds) all.push_back(&r);
    for (auto& r : dry_fine) all.push_back(&r);
    for (auto& e : dry_coarse)
        for (auto& r : e) all.push_back(&r);
    return all;
}

Study plan_study(const StudyPlan& plan) {
    validate_plan(plan);
    Study study;
    study.tolerances = plan.tolerances;
    study.reference.grain = {1.0, plan.exponents.front(), {}};
    study.reference.scene = plan.fine;
    auto with_seed = [&](StudyRun r, int i) {
        r.scene.seed = plan.fine.seed + static_cast<unsigned>(i);
        return r;
    };
    for (int i = 1; i < plan.seeds; ++i) study.replicas.push_back(with_seed(study.reference, i));
    std::vector<double> judged;
    for (double sf : plan.scale_factors)
        if (auto reasons = geometry_limits(plan.fine, sf); reasons.empty()) judged.push_back(sf);
        else study.limited.push_back({sf, std::move(reasons)});
    for (double k : plan.exponents)
        for (double sf : judged) {
            StudyRun r;
            r.grain = {sf, k, plan.scaled};
            r.scene = coarse_grained(plan.fine, r.grain);
            for (int i = 1; i < plan.seeds; ++i) study.coarse_seeds.push_back(with_seed(r, i));
            study.runs.push_back(std::move(r));
        }
    // The dry control: each scene without its liquid (equal dry scenes of several k run once).
    if (plan.fine.wet && plan.baseline == Baseline::dry) {
        auto dry = [&](StudyRun r) {
            r.scene.wet = r.scene.wet_walls = false;
            r.label = (r.grain.sf == 1 ? std::string("fine") : "S_f = " + format_short(r.grain.sf, 3)) + ", dry control";
            return r;
        };
        for (int i = 0; i < plan.seeds; ++i) study.dry_fine.push_back(dry(with_seed(study.reference, i)));
        for (const auto& r : study.runs) {
            study.dry_coarse.emplace_back();
            for (int i = 0; i < plan.seeds; ++i) study.dry_coarse.back().push_back(dry(with_seed(r, i)));
        }
    }
    return study;
}

void judge_study(Study& study, const StudyPlan& plan) {
    study.verdicts.clear(), study.corrected.clear(), study.controls.clear();
    for (const auto* r : study.fine_runs())
        if (!r->unusable.empty()) throw std::runtime_error("the fine scene's fill, seed " + std::to_string(r->scene.seed) + ": " + r->unusable);
    double reach = 0;  // the reference's radial grid covers every pile of the study
    for (const auto* r : study.all_runs()) reach = std::max(reach, r->result.final.spread_max);
    study.fine = fine_reference(study.fine_ensemble(), plan.fine.radius_m, reach);
    study.noise = noise_floor(study.fine_ensemble(), study.fine);
    for (auto* r : study.all_runs())
        if (r->unusable.empty()) r->versus_reference = compare_to(study.fine, r->result);
    for (std::size_t i = 0; i < study.runs.size(); ++i) {
        const double sf = study.runs[i].grain.sf, k = study.runs[i].grain.exponent;
        if (const auto why = study.unusable(i); !why.empty()) {  // a fill the cone could not hold: reported, not judged
            EnsembleVerdict v;
            v.sf = sf, v.exponent = k, v.unusable = why;
            study.verdicts.push_back(v);
            if (study.has_control()) study.corrected.push_back(v), study.controls.push_back(v);
            continue;
        }
        study.verdicts.push_back(judge_ensemble(study.fine_ensemble(), study.coarse_ensemble(i), sf, k, study.tolerances,
                                                plan.fine.radius_m, plan.fine.wet));
        if (!study.has_control()) continue;
        const DryControl control{study.dry_fine_ensemble(), study.dry_coarse_ensemble(i)};
        study.corrected.push_back(judge_ensemble(study.fine_ensemble(), study.coarse_ensemble(i), sf, k, study.tolerances,
                                                 plan.fine.radius_m, true, &control));
        study.controls.push_back(judge_ensemble(control.fine, control.coarse, sf, k, study.tolerances, plan.fine.radius_m, true));
        // The correction is first-order: say so where the control itself is far off or still moving.
        auto& corrected = study.corrected.back();
        if (study.controls.back().overall == stats::Verdict::fail)
            corrected.warnings.push_back("the dry control itself FAILs here (coarse and fine differ beyond the tolerances without liquid): "
                                         "the geometry dominates and removing it as an offset is a first-order correction");
        std::size_t moving = 0;
        for (const auto& side : {control.fine, control.coarse})
            for (const auto* r : side) moving += !r->came_to_rest;
        if (moving > 0)
            corrected.warnings.push_back(std::to_string(moving) + " of the dry control's " +
                                         std::to_string(control.fine.size() + control.coarse.size()) +
                                         " piles were still moving at the time limit (run.spread_time_s)");
    }
}

Study run_study(const StudyPlan& plan, const std::function<void(const std::string&)>& log) {
    const auto start = std::chrono::steady_clock::now();
    Study study = plan_study(plan);
    // S_f = 1 is the reference for every k; equal scenes run once.
    const auto all = study.all_runs();
    run_batch(all, {plan.jobs, plan.threads_per_job, plan.cache_dir, plan.force_dt, plan.fine.radius_m, plan.live, plan.slurm}, log);
    study.second_look = second_look(all);
    judge_study(study, plan);
    study.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return study;
}

}  // namespace demscale::slump
