// The verdict on one coarse ensemble (one S_f, one k, several seeds) against the fine ensemble:
// an equivalence test per measure (stats/verdict.hpp) on the 95 % interval of the difference,
//  slump   — Welch t interval of mean(s̄/H̄₀) − mean(s/H₀), tolerance absolute (a fraction of H₀);
//  spread  — Welch t interval of mean(d̄) − mean(d) (diameter at half height), over the fine mean, tolerance relative;
//  profile — bootstrap percentile interval (2 000 resamples of both ensembles' seeds, a fixed
//            generator seed so that a verdict repeats) of the distance between the two ensembles'
//            mean shapes (slump/comparison.hpp) with the part seed noise alone gives removed
//            (stats/shape_distance.hpp), tolerance relative; the distance is ≥ 0, so it passes
//            when the interval's top lies below the tolerance.
// Against a dry control (the same seeds of both scenes without their liquid), the same tests judge
// the difference after the geometry's offset is removed, seed by seed: for slump and spread the
// wet-minus-dry value of each seed, coarse against fine (Welch t); for the profile the distance
// ‖(c̄_wet − c̄_dry) − (f̄_wet − f̄_dry)‖ / ‖f̄_wet‖, bootstrapped over the seeds (a seed's wet and dry
// runs resampled together). docs/verdicts.md says why a dry control and what it cannot remove.
// It is INCONCLUSIVE, with a reason, where the data cannot decide: fewer than two seeds on a side,
// or a fine reference slumping less than one coarse diameter (then this scene cannot tell exponents
// apart by slump). Tolerances below the fine ensemble's own spread draw a warning.
#pragma once

#include <string>
#include <vector>

#include "slump/comparison.hpp"
#include "stats/verdict.hpp"

namespace demscale::slump {

struct Criterion {
    std::string measure;              // "slump", "spread", "profile"
    double estimate = 0;              // the difference (slump, spread) or distance (profile)
    stats::Interval interval;         // 95 %
    double tolerance = 0;
    stats::Verdict verdict = stats::Verdict::inconclusive;
    double smallest_tolerance = 0;    // the smallest tolerance these data could confirm
    std::string reason;               // why INCONCLUSIVE was forced, if it was
};

// The fine ensemble's own spread: the noise no tolerance should undercut.
struct NoiseFloor {
    stats::Summary slump_over_height;  // s/H₀ over the fine seeds
    stats::Summary spread;         // m
    stats::Summary profile;            // each fine run's shape distance from the fine mean shape
};
NoiseFloor noise_floor(const std::vector<const SlumpResult*>& fine, const FineReference& reference);

struct EnsembleVerdict {
    double sf = 1, exponent = 1;
    std::size_t fine_seeds = 0, coarse_seeds = 0;
    std::vector<Criterion> criteria;   // slump, spread, profile
    stats::Verdict overall = stats::Verdict::inconclusive;
    std::vector<std::string> warnings;
    std::string unusable;              // non-empty: a run's fill could not be used (why); no criteria, no part of any verdict
};

// What a wet study compares beside the raw difference: nothing, or a dry control that decides.
enum class Baseline { none, dry };

// The dry control of one comparison: the same seeds, in the same order, without the liquid.
struct DryControl {
    std::vector<const SlumpResult*> fine, coarse;
};

// Slump over the fill height, s/H₀: the scale-free slump every comparison uses.
double slump_over_height(const SlumpResult& r);

// A difference of means judged for equivalence: Welch t interval of mean(coarse) − mean(fine), both
// over scale (1: absolute; the fine mean: relative), against ±tolerance; INCONCLUSIVE with its
// reason when a side has fewer than two seeds. The slump and spread criteria of judge_ensemble and
// of a runs file (slump/runs_verdict.hpp) alike.
Criterion difference_criterion(const std::string& measure, const std::vector<double>& fine, const std::vector<double>& coarse,
                               double scale, double tolerance);

// Over the ensembles that decide (unusable ones left out): PASS if every one passes (an
// intersection-union test), FAIL if some criterion fails at the family's level (stats::fails_in_family,
// m = family_size), else INCONCLUSIVE, as when none was judged (docs/verdicts.md, "Levels of the test").
stats::Verdict family_verdict(const std::vector<EnsembleVerdict>& deciding);
std::size_t family_size(const std::vector<EnsembleVerdict>& deciding);

// fine_radius: m. wet: false adds the note that k has no effect.
// control: judge the offset-corrected difference (see above); its ensembles must match fine and
// coarse seed for seed (std::invalid_argument otherwise).
EnsembleVerdict judge_ensemble(const std::vector<const SlumpResult*>& fine, const std::vector<const SlumpResult*>& coarse,
                               double sf, double exponent, const Tolerances& tolerances, double fine_radius, bool wet,
                               const DryControl* control = nullptr);

}  // namespace demscale::slump
