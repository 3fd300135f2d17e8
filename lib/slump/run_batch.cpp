#include "slump/run_batch.hpp"

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
#include "slump/pour.hpp"

namespace demscale::slump {

namespace {

std::string describe(const StudyRun& r) {
    char b[200];
    if (!r.label.empty()) std::snprintf(b, sizeof b, "%s, seed %u", r.label.c_str(), r.scene.seed);
    else if (r.grain.sf == 1) std::snprintf(b, sizeof b, "fine, seed %u", r.scene.seed);
    else std::snprintf(b, sizeof b, "S_f = %g, k = %g, seed %u", r.grain.sf, r.grain.exponent, r.scene.seed);
    return b;
}

// Relative cost of a run, to start the longest first: particles ∝ S_f⁻³, steps ∝ 1/dt.
double expected_cost(const StudyRun& r, double reference_radius) {
    return std::pow(reference_radius / r.scene.radius_m, 3) / r.scene.dt_s;
}

// Time left: each run not started yet is predicted by the finished runs of its ensemble (the
// same scene but the seed: a standing column rests much later than a slumping one of the same
// size), else by its expected cost at the seconds per cost unit seen so far; over the jobs.
class TimeLeft {
public:
    TimeLeft(const std::vector<StudyRun*>& pending, double radius, int jobs) : pending_(pending), radius_(radius), jobs_(jobs) {
        for (const auto* r : pending) {
            SlumpScene s = r->scene;
            s.seed = 0;
            ensemble_.push_back(scene_key(s));
        }
    }
    void finished(std::size_t i) {
        const auto& r = *pending_[i];
        done_cost_ += expected_cost(r, radius_), done_wall_ += r.result.wall_s;
        auto& e = ensemble_wall_[ensemble_[i]];
        e.first += r.result.wall_s, ++e.second;
    }
    double seconds(std::size_t first_unstarted) const {
        double left = 0;
        for (std::size_t i = first_unstarted; i < pending_.size(); ++i) {
            const auto e = ensemble_wall_.find(ensemble_[i]);
            left += e != ensemble_wall_.end() ? e->second.first / e->second.second
                                              : expected_cost(*pending_[i], radius_) * done_wall_ / std::max(done_cost_, 1e-300);
        }
        return left / jobs_;
    }

private:
    const std::vector<StudyRun*>& pending_;
    double radius_;
    int jobs_;
    std::vector<std::string> ensemble_;                            // each pending run's scene key without its seed
    std::map<std::string, std::pair<double, int>> ensemble_wall_;  // seconds summed, runs
    double done_cost_ = 0, done_wall_ = 0;
};

// The live line: each job's current run and phase, redrawn at most twice a second. Its callers
// hold `mutex` when they clear a job's entry.
class LiveLine {
public:
    LiveLine(const std::function<void(const std::string&)>& live, int jobs, std::mutex& mutex)
        : live_(live), running_(static_cast<std::size_t>(jobs)), mutex_(mutex) {}
    std::function<void(const SlumpProgress&)> progress(std::size_t job, const std::string& who) {
        if (!live_) return {};
        return [this, job, who](const SlumpProgress& p) {
            char b[200];
            std::snprintf(b, sizeof b, "%s: %s t = %.2f/%.2f s", who.c_str(), p.phase.c_str(), p.time, p.phase_end);
            const std::lock_guard lock(mutex_);
            running_[job] = b;
            const auto now = std::chrono::steady_clock::now();
            if (now - last_ < std::chrono::milliseconds(500)) return;
            last_ = now;
            std::string line;
            for (const auto& r : running_)
                if (!r.empty()) line += (line.empty() ? "" : " | ") + r;
            live_(line);
        };
    }
    void clear(std::size_t job) { running_[job].clear(); }
    void end() {
        if (live_) live_("");
    }

private:
    const std::function<void(const std::string&)>& live_;
    std::vector<std::string> running_;
    std::mutex& mutex_;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// The pending runs o.jobs at a time on threads of this process, each cached as it finishes (a run
// interrupted earlier continues from its checkpoint). Throws as run_batch does.
void run_here(const std::vector<StudyRun*>& pending, RunCache* cache, const BatchOptions& o,
              const std::function<void(const std::string&)>& log) {
    const int job_count = std::max(1, std::min<int>(o.jobs, static_cast<int>(pending.size())));
    TimeLeft time_left(pending, o.reference_radius_m, job_count);
    std::mutex log_mutex;
    LiveLine live(o.live, job_count, log_mutex);
    std::atomic<std::size_t> next{0}, finished{0}, interrupted{0}, next_job{0};
    std::exception_ptr failure;
    auto worker = [&] {
        omp_set_num_threads(o.threads_per_job);  // this thread's own OpenMP setting
        const std::size_t job = next_job++;
        for (std::size_t i; (i = next++) < pending.size();) {
            StudyRun& r = *pending[i];
            try {
                if (failure) return;
                SlumpPhases phases;
                if (cache) phases.checkpoint = cache->dir() / (r.key + ".ckpt");
                if (cache && r.scene.liggghts_ranks > 0) phases.work_dir = cache->dir() / "liggghts" / r.key;  // deck, log, dump kept
                const bool resumed = cache && std::filesystem::exists(phases.checkpoint);
                if (resumed) phases.resume = phases.checkpoint;
                r.result = run_slump(r.scene, live.progress(job, describe(r)), o.force_dt, phases);
                if (cache) cache->store(r.key, r.result, o.threads_per_job), std::filesystem::remove(phases.checkpoint);
                const std::lock_guard lock(log_mutex);
                live.clear(job);
                time_left.finished(i);
                if (log) {
                    const double left = time_left.seconds(std::min<std::size_t>(next, pending.size()));
                    char b[300];
                    std::snprintf(b, sizeof b, "[%zu/%zu] %s: %zu particles, %zu steps, %.1f s%s; about %.0f s left", ++finished,
                                  pending.size(), describe(r).c_str(), r.result.particles, r.result.steps, r.result.wall_s,
                                  resumed ? " (resumed from its checkpoint)" : "", left);
                    log(b);
                }
            } catch (const Interrupted&) {
                const std::lock_guard lock(log_mutex);
                ++interrupted;
                if (!failure) failure = std::current_exception();
            } catch (const FillShortfall& e) {  // not a failure of the batch: a run the study reports as unusable
                const std::lock_guard lock(log_mutex);
                r.unusable = e.what();
                if (cache) cache->store_unusable(r.key, r.unusable);
                live.clear(job);
                ++finished;
                if (log) log("[" + std::to_string(finished) + "/" + std::to_string(pending.size()) + "] " + describe(r) + ": UNUSABLE, " + e.what());
            } catch (const InputError&) {
                const std::lock_guard lock(log_mutex);
                if (!failure) failure = std::current_exception();
            } catch (const std::exception& e) {  // name the run that failed
                const std::lock_guard lock(log_mutex);
                if (!failure) failure = std::make_exception_ptr(std::runtime_error(describe(r) + ": " + e.what()));
            } catch (...) {
                const std::lock_guard lock(log_mutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < std::min<int>(o.jobs, static_cast<int>(pending.size())); ++j) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    live.end();
    if (interrupted > 0 && cache)
        throw Interrupted(std::to_string(finished) + " of " + std::to_string(pending.size()) + " runs finished and cached, " +
                              std::to_string(interrupted) + " checkpointed; run the same command again to continue",
                          cache->dir().string());
    if (failure) std::rethrow_exception(failure);
}

}  // namespace

void run_batch(const std::vector<StudyRun*>& all, const BatchOptions& o, const std::function<void(const std::string&)>& log) {
    std::map<std::string, StudyRun*> unique;  // distinct scenes only
    for (auto* r : all) {
        r->key = scene_key(r->scene);
        unique.emplace(r->key, r);
    }
    if (o.slurm && !o.cache_dir)
        throw InputError("--backend", "slurm", "a cache folder (drop --no-cache): the Slurm tasks hand their results back through it");
    std::optional<RunCache> cache;
    if (o.cache_dir) cache.emplace(*o.cache_dir);
    std::vector<StudyRun*> pending;
    for (auto& [key, r] : unique) {
        if (cache) {
            if (auto hit = cache->load(key)) {
                r->result = std::move(*hit);
                r->from_cache = true;
                continue;
            }
            if (auto why = cache->load_unusable(key)) {  // its pour failed before: not poured again
                r->unusable = std::move(*why);
                r->from_cache = true;
                continue;
            }
        }
        pending.push_back(r);
    }
    const double radius = o.reference_radius_m;  // costliest first
    std::sort(pending.begin(), pending.end(),
              [&](const StudyRun* a, const StudyRun* b) { return expected_cost(*a, radius) > expected_cost(*b, radius); });
    if (log)
        log(std::to_string(unique.size()) + " distinct runs, " + std::to_string(unique.size() - pending.size()) + " cached, " +
            std::to_string(pending.size()) + " to run (" + (o.slurm ? std::string("on Slurm") : std::to_string(o.jobs) + " at a time") +
            ", " + std::to_string(o.threads_per_job) + " thread(s) each" +
            (!pending.empty() && pending.front()->scene.liggghts_ranks > 0
                 ? "; LIGGGHTS lifts and spreads on " + std::to_string(pending.front()->scene.liggghts_ranks) + " MPI ranks"
                 : std::string()) +
            ")");

    if (o.slurm && !pending.empty()) {
        std::vector<SlurmRun> handed;
        for (const auto* r : pending) handed.push_back({r->key, &r->scene});
        const auto round = submit_to_slurm(handed, *cache, o.threads_per_job, o.force_dt, *o.slurm, log);
        if (!o.slurm->wait)
            throw RunsPending(round.summary() + "; run the same command again to collect them (squeue shows the queue)");
        auto results = wait_for_slurm(handed, *cache, *o.slurm, log);
        for (std::size_t i = 0; i < pending.size(); ++i) pending[i]->result = std::move(results[i]);  // run by this call, on Slurm
        pending.clear();
    }

    run_here(pending, cache ? &*cache : nullptr, o, log);

    for (auto* r : all) {
        const StudyRun& ran = *unique.at(r->key);
        if (r != &ran) r->result = ran.result, r->from_cache = ran.from_cache, r->unusable = ran.unusable;
        r->warnings = geometry_warnings(r->scene, r->result.particles);
    }
}

}  // namespace demscale::slump
