// What a wet scene's liquid bridges should be announced with: the sphere–sphere fit's own validity
// findings at the scene's V̂ and θ, and with wet walls on Mikami's wall fit that fit's, with its
// force at contact against the exact sphere–plane bridge (docs/bridge-models.md). Empty for a dry
// scene and for exact ("table") curves, which it solves: InputError where they have no bridge.
#pragma once

#include <string>
#include <vector>

#include "slump/slump_scene.hpp"

namespace demscale::slump {

std::vector<std::string> bridge_warnings(const SlumpScene& s);

}  // namespace demscale::slump
