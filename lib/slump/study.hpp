// A coarse-graining study of the slump test: the fine reference and, for every candidate exponent k
// and scale factor S_f, the coarse run, each compared to the reference. Runs are independent, so
// they run side by side (jobs × threads each), costliest first; each finished run is cached by its
// scene key at once, so an interrupted study resumes where it stopped.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "slump/coarse_grain.hpp"
#include "slump/comparison.hpp"
#include "slump/run_cache.hpp"

namespace demscale::slump {

struct StudyPlan {
    SlumpScene fine;
    std::vector<double> scale_factors = {1.40, 1.96, 2.74, 3.84};  // Table 1, relative to R
    std::vector<double> exponents = {1, 3};
    std::vector<std::string> scaled;  // parameters scaled by the implied basis (coarse_grain.hpp)
    Tolerances tolerances;            // usually the scene's
    int replicas = 1;                 // extra fine runs with seeds seed+1…: the fine-vs-fine noise floor
    int jobs = 1, threads_per_job = 1;
    std::optional<std::filesystem::path> cache_dir;  // none: run everything
    bool force_dt = false;
};

struct StudyRun {
    CoarseGraining grain;
    SlumpScene scene;
    std::string key;
    std::vector<std::string> warnings;  // geometry limits (coarse_grain.hpp)
    SlumpResult result;
    bool from_cache = false;
    RunComparison versus_reference;     // zero for the reference itself
    bool within_tolerance = true;
};

struct Study {
    StudyRun reference;
    std::vector<StudyRun> replicas;  // the fine scene with other seeds, compared like coarse runs
    std::vector<StudyRun> runs;      // exponent-major, then S_f in the plan's order
    Tolerances tolerances;
    double wall_s = 0;           // this call's wall time (cached runs cost nothing)
    bool all_within() const;  // every coarse run (replicas are not judged)
    // The largest |error| between the reference and its replicas (zero without replicas).
    RunComparison noise_floor() const;
    // The run with the smallest profile error at this S_f, over the exponents.
    const StudyRun& best_at(double sf) const;
};

// Throws InputError for a bad plan: jobs, threads, replicas, exponents, any coarse scene.
void validate_plan(const StudyPlan& plan);

// Validates the whole plan (every coarse scene) before running anything. Progress lines go to log.
// Throws InputError for a bad plan and std::runtime_error when a run fails.
Study run_study(const StudyPlan& plan, const std::function<void(const std::string&)>& log = {});

}  // namespace demscale::slump
