// Running many slump scenes: each distinct scene (by its key) once, cached ones loaded, the rest
// side by side (jobs × threads each), costliest first. Each finished run is cached at once, so an
// interrupted batch resumes where it stopped; progress lines say how many remain and about how long.
// Or, with a Slurm backend, the uncached runs go to Slurm as a job array (slump/slurm_backend.hpp).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "slump/coarse_grain.hpp"
#include "slump/comparison.hpp"
#include "slump/run_cache.hpp"
#include "slump/slurm_backend.hpp"

namespace demscale::slump {

struct StudyRun {
    CoarseGraining grain;
    SlumpScene scene;
    std::string key;
    std::vector<std::string> warnings;  // geometry limits (coarse_grain.hpp)
    SlumpResult result;
    bool from_cache = false;
    RunComparison versus_reference;     // against the fine ensemble's means
    std::string label;                  // for progress lines; empty: from grain and seed
    std::string unusable;               // why its fill could not be used as a column (FillShortfall); empty: a column
};

struct BatchOptions {
    int jobs = 1, threads_per_job = 1;
    std::optional<std::filesystem::path> cache_dir;  // none: run everything
    bool force_dt = false;
    double reference_radius_m = 1e-3;  // to rank runs by cost (particles ∝ (R/R̄)³, steps ∝ 1/dt)
    // The runs in progress, one line (who, phase, simulated time of the phase's latest end), about
    // twice a second while any run is going and "" when the batch ends; none: not reported.
    std::function<void(const std::string&)> live;
    // Hand the uncached runs to Slurm instead of running them here (needs cache_dir).
    std::optional<SlurmSettings> slurm;
};

// Runs handed to a cluster and not finished yet: what() says which and how to collect them.
class RunsPending : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Fills every run's key, result, from_cache and warnings. Throws std::runtime_error when a run
// fails, Interrupted (with the cache folder) on an interrupt after checkpointing, and RunsPending
// when runs went to Slurm and options.slurm->wait is off. InputError: Slurm without a cache.
void run_batch(const std::vector<StudyRun*>& runs, const BatchOptions& options,
               const std::function<void(const std::string&)>& log = {});

}  // namespace demscale::slump
