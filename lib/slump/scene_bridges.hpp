// The curves a wet scene's bridges follow and its bridge law, as dem/bridge_law.hpp builds them
// from the scene's choices (liquid.bridge_variant, liquid.wall_bridge: bridge/curve_sources.hpp)
// with the scene's liquid per bridge V̂ (Eq. 5); errors name the scene file.
#pragma once

#include <string>

#include "bridge/bridge_curve.hpp"
#include "dem/laws/cohesion.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// Throw InputError naming liquid.bridge_variant or liquid.wall_bridge where the chosen source has
// no bridge at the scene's V̂ and θ.
bridge::BridgeCurve particle_bridge_curve(const SlumpScene& s);
bridge::BridgeCurve wall_bridge_curve(const SlumpScene& s);

// The wet scene's bridge law: both curves, the liquid per bridge from Eq. 5 with the particle mass
// (one V̂ for every pair), its viscous part; largest_radius (m) sets the range.
dem::CohesionLiquidBridge scene_bridge(const SlumpScene& s, double largest_radius);

std::string bridge_variant_name(const SlumpScene& s);  // the value of liquid.bridge_variant: mikami1998, table, ...
std::string wall_bridge_name(const SlumpScene& s);     // the value of liquid.wall_bridge

}  // namespace demscale::slump
