// Tables and files of the measured exponent (slump/response_study.hpp): the response curves
// (slump over height and spread per S_f and surface tension, with 95 % intervals), k̂ per S_f and
// jointly against the similarity groups' exponents, the dry control, and a figure of the raw and
// collapsed curves with the residual against k. Written atomically; PNG only when asked.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/table_format.hpp"
#include "slump/response_study.hpp"

namespace demscale::report {

// One line on a transition-model fit: k̂ with its interval and the runs it rests on, the similarity
// groups inside, and (with pass) the range of k whose slump stays within ±tolerance (of the fill height).
std::string describe_fit(const stats::TransitionFit& fit, const stats::PassingRange* pass, double tolerance);

io::Table response_table(const slump::ResponseStudy& study, const std::string& scene_label);
io::Table exponent_estimate_table(const slump::ResponseStudy& study, const std::string& scene_label);
io::Table dry_baseline_table(const slump::ResponseStudy& study, const std::string& scene_label);

struct EstimateFiles {
    std::vector<std::filesystem::path> written;
    std::filesystem::path figure_png;  // empty when not drawn
};

EstimateFiles write_estimate_files(const slump::ResponseStudy& study, const std::string& scene_label,
                                   const std::filesystem::path& out_dir, bool render_png);

}  // namespace demscale::report
