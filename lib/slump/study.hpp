// A coarse-graining study of the slump test: an ensemble of fine runs (seeds seed, seed+1, …) and,
// for every candidate exponent k and scale factor S_f, an ensemble of coarse runs with the same
// seeds, judged against the fine ensemble (slump/ensemble_verdict.hpp). A wet scene's study also
// runs its dry control by default: the fine and every coarse scene without the liquid, the same
// seeds, so that each coarse ensemble is judged twice, raw and after removing the offset the same
// S_f shows without any cohesion (docs/verdicts.md). The runs go through run_batch: side by side,
// cached, resumable.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "slump/coarse_grain.hpp"
#include "slump/comparison.hpp"
#include "slump/ensemble_verdict.hpp"
#include "slump/run_batch.hpp"
#include "slump/second_look.hpp"
#include "slump/run_cache.hpp"

namespace demscale::slump {

struct StudyPlan {
    SlumpScene fine;
    std::vector<double> scale_factors = {1.40, 1.96, 2.74, 3.84};  // Table 1, relative to R
    std::vector<double> exponents = {1, 3};
    std::vector<std::string> scaled;  // parameters scaled by the implied basis (coarse_grain.hpp)
    Tolerances tolerances;            // usually the scene's
    int seeds = 8;                    // runs per ensemble, fine and each coarse (S_f, k): seeds seed … seed+seeds−1
    Baseline baseline = Baseline::dry;  // ignored for a dry scene (its raw verdict is its control)
    int jobs = 1, threads_per_job = 1;
    std::optional<std::filesystem::path> cache_dir;  // none: run everything
    bool force_dt = false;
    std::function<void(const std::string&)> live;  // the runs in progress (BatchOptions::live)
    std::optional<SlurmSettings> slurm;            // hand the runs to Slurm (BatchOptions::slurm)
};

// An S_f the study did not run: its coarse scene is geometry-limited (slump/coarse_grain.hpp).
struct LimitedScale {
    double sf = 1;
    std::vector<std::string> reasons;
};

struct Study {
    std::vector<LimitedScale> limited;  // in the plan's order; no runs, no verdict
    StudyRun reference;                 // the fine run with the scene's own seed
    std::vector<StudyRun> replicas;     // the fine runs with the other seeds
    std::vector<StudyRun> runs;         // coarse runs with the scene's seed: exponent-major, then the judged S_f in the plan's order
    std::vector<StudyRun> coarse_seeds; // coarse runs with the other seeds, in the same order, seed-minor
    std::vector<EnsembleVerdict> verdicts;  // raw: one per entry of runs
    std::vector<StudyRun> dry_fine;                 // with a dry control: the fine scene without liquid, every seed, fine_ensemble()'s order
    std::vector<std::vector<StudyRun>> dry_coarse;  // per entry of runs: its coarse scene without liquid, coarse_ensemble()'s order
    std::vector<EnsembleVerdict> corrected;         // per entry of runs: after removing the dry control's offset
    std::vector<EnsembleVerdict> controls;          // per entry of runs: the dry coarse ensemble against the dry fine one
    FineReference fine;                 // the fine ensemble's means and mean shape
    NoiseFloor noise;                   // the fine ensemble's own spread
    Tolerances tolerances;
    SecondLook second_look;             // more seeds added to a study already run
    double wall_s = 0;                  // this call's wall time (cached runs cost nothing)
    bool has_control() const { return !dry_fine.empty(); }
    // The verdicts that decide: baseline-corrected with a dry control, else raw.
    const std::vector<EnsembleVerdict>& deciding() const { return has_control() ? corrected : verdicts; }
    // Over the deciding verdicts (geometry-limited S_f have none): PASS if every criterion passes
    // (an intersection-union test: no correction); FAIL if some criterion fails at the family's
    // level (stats::fails_in_family, m = family_size()); else INCONCLUSIVE, as when no S_f could be judged.
    stats::Verdict overall() const;
    std::size_t family_size() const;  // the criteria of every judged ensemble that decides
    std::vector<double> judged_scale_factors() const;  // the S_f with verdicts, in the plan's order
    std::vector<const SlumpResult*> fine_ensemble() const;
    std::vector<const StudyRun*> coarse_runs(std::size_t run) const;         // runs[run] and its other seeds
    std::vector<const SlumpResult*> coarse_ensemble(std::size_t run) const;  // their results
    std::vector<const StudyRun*> fine_runs() const;  // the fine ensemble's runs and its dry control's
    // Why ensemble `run` (its coarse runs and their dry control) cannot be judged: how many of its
    // fills the cone could not hold, and the first one's reason; empty when every fill is a column.
    std::string unusable(std::size_t run) const;
    std::vector<const SlumpResult*> dry_fine_ensemble() const;
    std::vector<const SlumpResult*> dry_coarse_ensemble(std::size_t run) const;
    std::vector<StudyRun*> all_runs();  // reference, replicas, runs, coarse_seeds, then the dry control
    std::vector<const StudyRun*> all_runs() const;
    // The deciding verdict with the smallest profile distance at this S_f, over the exponents.
    const EnsembleVerdict& best_at(double sf) const;
    // The best's uncertainty: the other exponents at this S_f whose profile interval reaches below the
    // top of the best's, so that the seeds cannot tell them from it (overlapping 95 % intervals: a
    // conservative test, docs/verdicts.md).
    std::vector<double> not_told_apart_from_best(double sf) const;
};

// Throws InputError for a bad plan: jobs, threads, replicas, exponents, any coarse scene.
void validate_plan(const StudyPlan& plan);

// The study's runs, not run yet (results empty), after validate_plan.
Study plan_study(const StudyPlan& plan);

// The verdicts of a study whose runs have results: the fine reference and noise, each run against
// it, and per coarse ensemble the raw verdict and, with a dry control, the corrected one and the
// control's; an ensemble with an unusable fill gets a verdict that says so and nothing else.
// Throws std::runtime_error when a fine fill is unusable (the scene itself cannot be filled).
void judge_study(Study& study, const StudyPlan& plan);

// Validates the whole plan (every coarse scene) before running anything. Progress lines go to log.
// Throws InputError for a bad plan and std::runtime_error when a run fails.
Study run_study(const StudyPlan& plan, const std::function<void(const std::string&)>& log = {});

}  // namespace demscale::slump
