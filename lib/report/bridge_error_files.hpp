// Writes a bridge-error study: points and summary CSV, a heat map of Mikami's error over
// (V̂, ĥ/ĥ_rupture) at θ = 0, and the speed-against-error plot — each atomically.
#pragma once

#include <filesystem>
#include <vector>

#include "report/bridge_error.hpp"

namespace demscale::report {

std::vector<std::filesystem::path> write_bridge_error_files(const BridgeErrorStudy& study,
                                                            const std::filesystem::path& out_dir, bool render_png);

}  // namespace demscale::report
