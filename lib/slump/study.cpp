#include "slump/study.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <omp.h>
#include <thread>

#include "core/input_error.hpp"
#include "core/interrupt.hpp"

namespace demscale::slump {

stats::Verdict Study::overall() const {
    std::vector<stats::Verdict> v;
    for (const auto& e : verdicts) v.push_back(e.overall);
    return v.empty() ? stats::Verdict::inconclusive : stats::combine(v);
}

std::vector<const SlumpResult*> Study::fine_ensemble() const {
    std::vector<const SlumpResult*> f = {&reference.result};
    for (const auto& r : replicas) f.push_back(&r.result);
    return f;
}

std::vector<const SlumpResult*> Study::coarse_ensemble(std::size_t i) const {
    std::vector<const SlumpResult*> c = {&runs.at(i).result};
    const std::size_t others = runs.empty() ? 0 : coarse_seeds.size() / runs.size();
    for (std::size_t j = 0; j < others; ++j) c.push_back(&coarse_seeds.at(i * others + j).result);
    return c;
}

const EnsembleVerdict& Study::best_at(double sf) const {
    const EnsembleVerdict* best = nullptr;
    for (const auto& v : verdicts)
        if (v.sf == sf && (!best || v.criteria.at(2).estimate < best->criteria.at(2).estimate)) best = &v;
    if (!best) throw InputError("--sf", format_number(sf), "one of the study's scale factors");
    return *best;
}

namespace {

std::string describe(const StudyRun& r) {
    char b[160];
    if (r.grain.sf == 1) std::snprintf(b, sizeof b, "fine, seed %u", r.scene.seed);
    else std::snprintf(b, sizeof b, "S_f = %g, k = %g, seed %u", r.grain.sf, r.grain.exponent, r.scene.seed);
    return b;
}

// Relative cost of a run, to start the longest first: particles ∝ S_f⁻³, steps ∝ 1/dt.
double expected_cost(const StudyRun& r, const SlumpScene& fine) {
    return std::pow(fine.radius_m / r.scene.radius_m, 3) / r.scene.dt_s;
}

}  // namespace

void validate_plan(const StudyPlan& plan) {
    if (plan.jobs < 1) throw InputError("--jobs", std::to_string(plan.jobs), ">= 1");
    if (plan.threads_per_job < 1) throw InputError("--threads", std::to_string(plan.threads_per_job), ">= 1");
    if (plan.exponents.empty()) throw InputError("--exponents", "(none)", "at least one exponent");
    if (plan.seeds < 1 || plan.seeds > 64) throw InputError("--seeds", std::to_string(plan.seeds), "1 to 64 (runs per ensemble)");
    check_slump_time_step(plan.fine, plan.force_dt);
    for (double k : plan.exponents)
        for (double sf : plan.scale_factors) check_slump_time_step(coarse_grained(plan.fine, {sf, k, plan.scaled}), plan.force_dt);
}

Study run_study(const StudyPlan& plan, const std::function<void(const std::string&)>& log) {
    const auto start = std::chrono::steady_clock::now();
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
    for (double k : plan.exponents)
        for (double sf : plan.scale_factors) {
            StudyRun r;
            r.grain = {sf, k, plan.scaled};
            r.scene = coarse_grained(plan.fine, r.grain);
            for (int i = 1; i < plan.seeds; ++i) study.coarse_seeds.push_back(with_seed(r, i));
            study.runs.push_back(std::move(r));
        }
    // Distinct scenes only: S_f = 1 is the reference for every k; equal scenes run once.
    std::map<std::string, StudyRun*> unique;
    std::vector<StudyRun*> all = {&study.reference};
    for (auto& r : study.replicas) all.push_back(&r);
    for (auto& r : study.runs) all.push_back(&r);
    for (auto& r : study.coarse_seeds) all.push_back(&r);
    for (auto* r : all) {
        r->key = scene_key(r->scene);
        unique.emplace(r->key, r);
    }
    std::optional<RunCache> cache;
    if (plan.cache_dir) cache.emplace(*plan.cache_dir);
    std::vector<StudyRun*> pending;
    for (auto& [key, r] : unique) {
        if (cache)
            if (auto hit = cache->load(key)) {
                r->result = std::move(*hit);
                r->from_cache = true;
                continue;
            }
        pending.push_back(r);
    }
    std::sort(pending.begin(), pending.end(),
              [&](const StudyRun* a, const StudyRun* b) { return expected_cost(*a, plan.fine) > expected_cost(*b, plan.fine); });
    if (log)
        log(std::to_string(unique.size()) + " distinct runs, " + std::to_string(unique.size() - pending.size()) + " cached, " +
            std::to_string(pending.size()) + " to run (" + std::to_string(plan.jobs) + " at a time, " +
            std::to_string(plan.threads_per_job) + " thread(s) each)");

    double total_cost = 0, done_cost = 0;
    for (const auto* r : pending) total_cost += expected_cost(*r, plan.fine);
    const auto runs_start = std::chrono::steady_clock::now();
    std::mutex log_mutex;
    std::atomic<std::size_t> next{0}, finished{0}, interrupted{0};
    std::exception_ptr failure;
    auto worker = [&] {
        omp_set_num_threads(plan.threads_per_job);  // this thread's own OpenMP setting
        for (std::size_t i; (i = next++) < pending.size();) {
            StudyRun& r = *pending[i];
            try {
                if (failure) return;
                // A run interrupted earlier left its checkpoint beside the cache: continue it.
                SlumpPhases phases;
                if (cache) phases.checkpoint = cache->dir() / (r.key + ".ckpt");
                const bool resumed = cache && std::filesystem::exists(phases.checkpoint);
                if (resumed) phases.resume = phases.checkpoint;
                r.result = run_slump(r.scene, {}, plan.force_dt, phases);
                if (cache) cache->store(r.key, r.result, plan.threads_per_job), std::filesystem::remove(phases.checkpoint);
                const std::lock_guard lock(log_mutex);
                done_cost += expected_cost(r, plan.fine);
                if (log) {
                    // Time left: the elapsed time scaled by the expected cost still to run.
                    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - runs_start).count();
                    const double left = done_cost > 0 ? elapsed * (total_cost - done_cost) / done_cost : 0;
                    char b[260];
                    std::snprintf(b, sizeof b, "[%zu/%zu] %s: %zu particles, %zu steps, %.1f s%s; about %.0f s left", ++finished,
                                  pending.size(), describe(r).c_str(), r.result.particles, r.result.steps, r.result.wall_s,
                                  resumed ? " (resumed from its checkpoint)" : "", left);
                    log(b);
                }
            } catch (const Interrupted&) {
                const std::lock_guard lock(log_mutex);
                ++interrupted;
                if (!failure) failure = std::current_exception();
            } catch (...) {
                const std::lock_guard lock(log_mutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < std::min<int>(plan.jobs, static_cast<int>(pending.size())); ++j) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    if (interrupted > 0 && cache)
        throw Interrupted(std::to_string(finished) + " of " + std::to_string(pending.size()) + " runs finished and cached, " +
                              std::to_string(interrupted) + " checkpointed; run the same command again to continue",
                          cache->dir().string());
    if (failure) std::rethrow_exception(failure);

    for (auto* r : all) {
        const StudyRun& ran = *unique.at(r->key);
        if (r != &ran) r->result = ran.result, r->from_cache = ran.from_cache;
        r->warnings = geometry_warnings(r->scene, r->result.particles);
    }
    double reach = 0;  // the reference's radial grid covers every pile of the study
    for (const auto* r : all) reach = std::max(reach, r->result.final.spread_max);
    study.fine = fine_reference(study.fine_ensemble(), plan.fine.radius_m, reach);
    study.noise = noise_floor(study.fine_ensemble(), study.fine);
    for (auto* r : all) r->versus_reference = compare_to(study.fine, r->result);
    for (std::size_t i = 0; i < study.runs.size(); ++i)
        study.verdicts.push_back(judge_ensemble(study.fine_ensemble(), study.coarse_ensemble(i), study.runs[i].grain.sf,
                                                study.runs[i].grain.exponent, study.tolerances, plan.fine.radius_m, plan.fine.wet));
    study.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return study;
}

}  // namespace demscale::slump
