// Response curves of the slump test to cohesion, and the exponent measured from them
// (docs/exponent-estimate.md). The fine scene runs at surface tensions γ_i = f_i·γ (the plan's
// factors), each an ensemble of seeds; each coarse S_f runs at γ̄_i = f_i·γ·S_f^offset, the same
// factors moved by a guessed exponent (default 2, between the groups' 1 and 3) so that its levels
// straddle the fine transition for any k near it. The response is slump over fill height, and the
// spread (diameter at half height) over the cone's bottom diameter. k̂ per S_f and jointly: stats/curve_shift.hpp.
// A wet scene's study also runs its dry control by default (the fine and each coarse scene without
// liquid, the same seeds): k̂ is then measured after subtracting the dry coarse − fine offset
// (stats/curve_shift.hpp, baseline), and once more raw, for comparison.
// A dry scene has no cohesion to vary: its one level per S_f is the dry control, the coarse −
// fine difference that no exponent can remove.
#pragma once

#include <vector>

#include "slump/ensemble_verdict.hpp"
#include "slump/run_batch.hpp"
#include "slump/second_look.hpp"
#include "slump/runs_file.hpp"
#include "stats/curve_shift.hpp"
#include "stats/passing_range.hpp"
#include "stats/transition_model.hpp"
#include "stats/summary.hpp"

namespace demscale::slump {

struct ResponsePlan {
    SlumpScene fine;
    std::vector<double> scale_factors = {1.40, 1.96};
    std::vector<double> factors = {0.5, 0.669, 0.894, 1.196, 1.6};  // of the scene's γ, ascending (dry: ignored)
    double offset_exponent = 1;  // coarse levels at f·γ·S_f^offset
    int seeds = 4;
    Baseline baseline = Baseline::dry;  // wet scenes: the dry control beside the levels
    BatchOptions batch;
    stats::ShiftSearch search;           // the means shift (comparison)
    stats::TransitionSettings transition;  // the transition model (decides)
};

struct ResponseEnsemble {
    double sf = 1;
    double gamma = 0;            // N/m (0 dry)
    std::vector<StudyRun> runs;  // one per seed (none when read from a runs file)
    std::vector<RunRow> measured;  // what the estimator reads of each run: from runs, or a runs file
    stats::Summary slump_over_height, spread_over_diameter;
    bool all_at_rest() const;
    std::string unusable() const;  // the first unusable fill's reason (RunRow::unusable); empty: every fill a column
};

// Coarse − fine at one S_f on a dry scene: the baseline error of coarse-graining the dry laws.
// The intervals are judge_ensemble's (slump, spread, profile; its verdicts are not used), the
// noise the fine ensemble's own (noise_floor).
struct DryBaseline {
    double sf = 1;
    std::vector<Criterion> criteria;  // slump, spread, profile
    NoiseFloor noise;
};

struct ResponseStudy {
    bool wet = true;
    std::vector<ResponseEnsemble> fine;                 // per level, ascending γ
    std::vector<std::vector<ResponseEnsemble>> coarse;  // per S_f (plan order), per level
    std::vector<ResponseEnsemble> dry_control;          // wet with a baseline: fine, then per S_f (plan order), no liquid
    std::vector<StudyRun*> all_runs();                  // fine, then coarse
    stats::ResponseCurve fine_curve;                    // slump over height against ln γ
    std::vector<stats::ResponseCurve> coarse_curves;
    // k per S_f then jointly (wet only), baseline-corrected with a dry control, then raw (with a dry
    // control only): the transition model decides, the means shift is shown beside it.
    std::vector<stats::TransitionFit> fits, raw_fits;
    std::vector<stats::ExponentEstimate> estimates;     // the means shift
    std::vector<stats::ExponentEstimate> raw_estimates;
    std::vector<stats::PassingRange> passing;           // the k that pass at the scene's slump tolerance, per S_f then jointly (from fits)
    stats::Interval fine_range;                         // the fine levels' ln γ, lowest and highest
    double stands_below = 0;                            // slump over fill height below which a run stood (the model's)
    bool has_control() const { return !dry_control.empty(); }
    std::vector<stats::SplitLevel> split;               // levels whose seeds split (wet only; stats::split_levels)
    std::vector<DryBaseline> baselines;                 // dry only
    SecondLook second_look;                             // more seeds added to a study already run (none read from a runs file)
    double wall_s = 0;
};

// Ensemble e's entry in study.split, or null when its seeds did not split.
const stats::SplitLevel* split_of(const ResponseStudy& study, const ResponseEnsemble& e);

// `levels` surface tension factors log-spaced from lo to hi, each rounded to 12 digits so that a
// level meant to be 1 (or 2) is exactly that and shares its cached runs with the study's. Throws
// InputError naming range_field or levels_field.
std::vector<double> log_spaced_factors(double lo, double hi, int levels, const std::string& range_field,
                                       const std::string& levels_field);

// Throws InputError for a bad plan (factors, offset, seeds, any scene).
void validate_response_plan(const ResponsePlan& plan);

// The study's ensembles with their scenes, nothing run yet (what run_response_study runs).
ResponseStudy plan_response_runs(const ResponsePlan& plan);

ResponseStudy run_response_study(const ResponsePlan& plan, const std::function<void(const std::string&)>& log = {});

// The study's measures of every run (fine, coarse, dry control), in that order: what runs.csv holds.
std::vector<RunRow> response_runs(const ResponseStudy& study);

// A wet study from a runs file's rows (slump/runs_file.hpp), judged as run_response_study judges
// its own runs: rows with S_f 1 make the fine curve, each S_f > 1 a coarse one, rows without liquid
// (γ = 0) the dry control. plan.fine gives γ and the tolerance; plan.scale_factors, factors and
// seeds are replaced by the file's. Throws InputError for rows that make no study (no fine levels,
// a dry control for some curves only).
ResponseStudy response_study_from_runs(const std::vector<RunRow>& rows, ResponsePlan plan, const std::string& source);

}  // namespace demscale::slump
