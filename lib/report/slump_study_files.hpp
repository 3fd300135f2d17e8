// Files of a slump study: the run table (CSV), every final profile (long CSV: sf, exponent,
// radius_mm, height_mm), and gnuplot figures — final profiles of all S_f over the reference (one
// panel per exponent), and for several exponents the error against k and against speed-up.
// Written atomically; PNGs only when asked and gnuplot is present.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "slump/study.hpp"

namespace demscale::report {

struct StudyFiles {
    std::vector<std::filesystem::path> written;
    std::filesystem::path profiles_png, error_png, front_png;  // empty when not drawn
};

StudyFiles write_study_files(const slump::Study& study, const std::string& scene_label, const std::filesystem::path& out_dir,
                             const std::string& stem, bool render_png);

}  // namespace demscale::report
