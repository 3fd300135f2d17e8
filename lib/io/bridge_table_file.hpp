// The tabulated exact bridge (bridge/bridge_table.hpp) as a CSV file: `#` lines with the grid, then
// one row per node (vhat, theta_deg, x = hhat/hhat_rupture, hhat_rupture, fhat), V̂-major.
#pragma once

#include <string>

#include "bridge/bridge_table.hpp"

namespace demscale::io {

// Throws InputError naming the file (and line) for a missing or ill-formed file.
bridge::BridgeTable read_bridge_table(const std::string& path);

std::string bridge_table_csv(const bridge::BridgeTable& table);

}  // namespace demscale::io
