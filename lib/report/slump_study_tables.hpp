// Tables of a slump coarse-graining study (check-exponent, sweep, report):
//  verdict_table  — one row per (S_f, k) ensemble (of a study, or of a runs file): the three criteria's 95 % intervals, the
//                   tolerances, PASS / FAIL / INCONCLUSIVE, and the smallest confirmable tolerance;
//  ensemble_table — one row per ensemble (the fine one first): means, spreads and costs;
//  study_table    — one row per run (every seed), against the fine ensemble's means;
//  best_exponent_table — per S_f, the exponent whose ensemble has the smallest profile distance.
// (The similarity groups each exponent keeps or breaks: report/similarity_table.hpp.)
#pragma once

#include <vector>

#include "io/table_format.hpp"
#include "slump/runs_verdict.hpp"
#include "slump/study.hpp"

namespace demscale::report {

io::Table verdict_table(const slump::Study& study, const std::string& scene_label);
// From a runs file (slump/runs_verdict.hpp): the same rows, the profile not judged; source names the file.
io::Table verdict_table(const slump::RunsVerdicts& verdicts, const std::string& scene_label, const std::string& source);
io::Table ensemble_table(const slump::Study& study, const std::string& scene_label);
io::Table study_table(const slump::Study& study, const std::string& scene_label);
io::Table best_exponent_table(const slump::Study& study, const std::vector<double>& scale_factors);

}  // namespace demscale::report
