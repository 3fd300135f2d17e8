// The report's table of a scene's inputs: geometry and protocol, the law selection, and every
// parameter of each law part that acts, as its table declares it (label, value, unit).
#pragma once

#include <span>
#include <string>

#include "dem/law_parts.hpp"
#include "io/table_format.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::report {

io::Table scene_table(const slump::SlumpScene& s, const std::string& label, std::span<const dem::LawPart> parts = dem::law_parts());

}  // namespace demscale::report
