// A verdict with three outcomes from an equivalence test (two one-sided tests, TOST, in interval
// form): with the 95 % confidence interval [lo, hi] of the coarse − fine difference d and a
// tolerance τ,
//   PASS         when the whole interval lies inside [−τ, τ]  (equivalent within τ),
//   FAIL         when it lies wholly outside it (lo > τ or hi < −τ: different by more than τ),
//   INCONCLUSIVE otherwise: the data cannot decide at this tolerance; more seeds narrow the interval.
// The smallest tolerance the data could confirm is max(|lo|, |hi|). For a one-sided measure that is
// ≥ 0 by construction (the profile distance) the test uses [lo, hi] against [0, τ] the same way.
#pragma once

#include <string>
#include <vector>

#include "stats/summary.hpp"

namespace demscale::stats {

enum class Verdict { pass, inconclusive, fail };

std::string verdict_name(Verdict v);  // "PASS", "INCONCLUSIVE", "FAIL"

Verdict equivalence_verdict(const Interval& difference, double tolerance);

// max(|lo|, |hi|): below it no tolerance could PASS with these data.
double smallest_confirmable_tolerance(const Interval& difference);

// The overall verdict of several criteria: FAIL if any fails, else INCONCLUSIVE if any is, else PASS.
Verdict combine(const std::vector<Verdict>& verdicts);

// A FAIL within a family of m criteria (docs/verdicts.md, "Levels of the test"): the command FAILs
// when any of m criteria FAILs, so one FAIL counts only if it holds at 5 % / m, Holm's first step
// (for "any rejection" the same as Bonferroni): the 95 % interval, widened about the estimate by
// z(1 − 0.025/m) / z(0.975), still lies wholly outside ±tolerance. m = 1 is the criterion's own FAIL.
bool fails_in_family(double estimate, const Interval& ci, double tolerance, std::size_t m);

}  // namespace demscale::stats
