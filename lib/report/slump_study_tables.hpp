// Tables of a slump coarse-graining study (check-exponent, sweep, report): one row per run against
// the fine reference; the exponent with the smallest profile error per S_f. (The similarity groups
// each exponent keeps or breaks: report/similarity_table.hpp.)
#pragma once

#include <vector>

#include "io/table_format.hpp"
#include "slump/study.hpp"

namespace demscale::report {

// Reference row first (S_f = 1), then every run. Errors in %, lengths in mm, wall time in s.
io::Table study_table(const slump::Study& study, const std::string& scene_label);

// Per S_f: the exponent with the smallest profile error, its errors and speed-up.
io::Table best_exponent_table(const slump::Study& study, const std::vector<double>& scale_factors);

}  // namespace demscale::report
