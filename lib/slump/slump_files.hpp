// The files of one slump run: final profile h(ρ), time history, final particle positions, a
// side-view picture of the final pile (particles drawn as circles, like Yun & Park's Fig. 5) and
// the final state for ParaView. Each written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "slump/slump_run.hpp"

namespace demscale::slump {

std::vector<std::filesystem::path> write_slump_files(const SlumpResult& r, const std::string& title,
                                                     const std::filesystem::path& out_dir, const std::string& stem,
                                                     bool render_png);

}  // namespace demscale::slump
