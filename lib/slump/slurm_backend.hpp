// Handing a batch's runs to Slurm as a job array (docs/cluster.md). Each run not in the cache is
// written beside it as its scene text (DIR/slurm/<key>.scene); one batch script lists them, and
// each array task runs one of them (`demscale cached-run`) into the same, shared cache folder. A
// later call finds the finished runs in the cache, leaves alone those still queued, and submits
// again those whose task ended without a result. Results are those of a local run, bit for bit:
// the task runs the very scene planned here, and a run's result does not depend on its threads.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "slump/run_cache.hpp"

namespace demscale::slump {

struct SlurmSettings {
    std::filesystem::path executable;         // the demscale each task runs (an absolute path)
    std::vector<std::string> sbatch_options;  // more #SBATCH lines, e.g. --partition=short, --time=2:00:00
    bool wait = false;                        // poll the queue until every run is cached, then go on
    double poll_s = 5;
};

// A run the batch needs and the cache lacks.
struct SlurmRun {
    std::string key;
    const SlumpScene* scene;
};

// What one call left outstanding, by key.
struct SlurmRound {
    std::vector<std::string> submitted;  // handed to Slurm by this call
    std::vector<std::string> queued;     // in the queue from an earlier call
    std::vector<std::string> lost;       // their task ended without a result: submitted again, logs named
    std::vector<std::string> jobs;       // the job ids the outstanding runs belong to
    std::vector<std::filesystem::path> lost_logs;
    std::string summary() const;         // one line for people
};

// Submits, as one job array, every run neither cached nor queued (costliest first, as given);
// cpus-per-task = threads. Throws std::runtime_error when sbatch or squeue fails or is missing.
SlurmRound submit_to_slurm(const std::vector<SlurmRun>& runs, const RunCache& cache, int threads, bool force_dt,
                           const SlurmSettings& settings, const std::function<void(const std::string&)>& log = {});

// Polls the queue until every run is cached; returns their results, in the order of runs (each
// read from the cache once). Throws std::runtime_error naming the logs when a task ends without a
// result, and Interrupted on SIGINT (the tasks go on in Slurm).
std::vector<SlumpResult> wait_for_slurm(const std::vector<SlurmRun>& runs, const RunCache& cache, const SlurmSettings& settings,
                    const std::function<void(const std::string&)>& log = {});

// What an array task does: reads DIR/slurm/<key>.scene, checks it is the scene of that key, runs
// it on `threads` threads (resuming a checkpoint an earlier, cancelled task left) and caches it.
void run_slurm_task(const std::filesystem::path& cache_dir, const std::string& key, int threads, bool force_dt,
                    const std::function<void(const std::string&)>& log = {});

}  // namespace demscale::slump
