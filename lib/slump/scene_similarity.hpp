// The similarity inputs (Table 1's shape: the physical particle, the coarse radii, the liquid and
// the bridge) that a slump scene implies, so that one scene file drives the similarity table,
// Figs. 3-4, their regression and the slump study alike.
#pragma once

#include <string>
#include <vector>

#include "io/table_config.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// The scene's particle is the physical one (S_f = 1); radii S_f·R for its [similarity]
// scale_factors; masses from its solid density (replacement, Eqs. 9-10); its liquid, bridge
// variant and rupture law; its candidate exponents. source = the scene's path.
io::TableConfig similarity_inputs(const SlumpScene& scene);

// The inputs on which a Table-1 configuration and a scene disagree, one "key: config X, scene Y"
// each (keys as written in the scene file); empty when they agree. The solid density counts only
// when the configuration states one (otherwise Table 1's masses imply it).
std::vector<std::string> differing_inputs(const io::TableConfig& config, const SlumpScene& scene);

}  // namespace demscale::slump
