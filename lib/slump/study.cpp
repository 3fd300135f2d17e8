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

bool Study::all_within() const {
    return std::all_of(runs.begin(), runs.end(), [](const StudyRun& r) { return r.within_tolerance; });
}

RunComparison Study::noise_floor() const {
    RunComparison n;
    for (const auto& r : replicas) {
        const auto& c = r.versus_reference;
        n.slump_error = std::max(n.slump_error, std::abs(c.slump_error));
        n.spread_error = std::max(n.spread_error, std::abs(c.spread_error));
        n.profile_error = std::max(n.profile_error, c.profile_error);
    }
    return n;
}

const StudyRun& Study::best_at(double sf) const {
    const StudyRun* best = nullptr;
    for (const auto& r : runs)
        if (r.grain.sf == sf && (!best || r.versus_reference.profile_error < best->versus_reference.profile_error)) best = &r;
    if (!best) throw InputError("--sf", format_number(sf), "one of the study's scale factors");
    return *best;
}

namespace {

std::string describe(const StudyRun& r) {
    char b[160];
    if (r.grain.sf == 1) std::snprintf(b, sizeof b, "fine, seed %u", r.scene.seed);
    else std::snprintf(b, sizeof b, "S_f = %g, k = %g", r.grain.sf, r.grain.exponent);
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
    if (plan.replicas < 0 || plan.replicas > 20) throw InputError("--replicas", std::to_string(plan.replicas), "0 to 20");
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
    for (int i = 1; i <= plan.replicas; ++i) {
        StudyRun r = study.reference;
        r.scene.seed = plan.fine.seed + static_cast<unsigned>(i);
        study.replicas.push_back(std::move(r));
    }
    for (double k : plan.exponents)
        for (double sf : plan.scale_factors) {
            StudyRun r;
            r.grain = {sf, k, plan.scaled};
            r.scene = coarse_grained(plan.fine, r.grain);
            study.runs.push_back(std::move(r));
        }
    // Distinct scenes only: S_f = 1 is the reference for every k; equal scenes run once.
    std::map<std::string, StudyRun*> unique;
    std::vector<StudyRun*> all = {&study.reference};
    for (auto& r : study.replicas) all.push_back(&r);
    for (auto& r : study.runs) all.push_back(&r);
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
                if (log) {
                    char b[220];
                    std::snprintf(b, sizeof b, "[%zu/%zu] %s: %zu particles, %zu steps, %.1f s%s", ++finished, pending.size(),
                                  describe(r).c_str(), r.result.particles, r.result.steps, r.result.wall_s,
                                  resumed ? " (resumed from its checkpoint)" : "");
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
    for (auto* r : all)
        if (r != &study.reference) {
            r->versus_reference = compare_runs(study.reference.result, r->result);
            r->within_tolerance = r->versus_reference.within(study.tolerances);
        }
    study.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return study;
}

}  // namespace demscale::slump
