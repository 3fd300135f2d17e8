// The curves a wet scene's bridges follow (docs/models/liquid-bridge.md): particle–particle as
// liquid.bridge_variant says (a Mikami fit, or "table": the exact bridge at the scene's V̂ and θ),
// particle–wall as liquid.wall_bridge says ("table", the default: the exact sphere–plane bridge with
// θ on both surfaces; "mikami1998": Mikami's sphere–wall fit). An exact column is solved once per
// process for each (V̂, θ, geometry) and shared between runs and threads.
#pragma once

#include <string>

#include "bridge/bridge_curve.hpp"
#include "dem/laws/cohesion.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// Throw InputError naming liquid.bridge_variant or liquid.wall_bridge where the exact solver finds
// no concave bridge at the scene's V̂ and θ.
bridge::BridgeCurve particle_bridge_curve(const SlumpScene& s);
bridge::BridgeCurve wall_bridge_curve(const SlumpScene& s);

// The wet scene's bridge law: both curves, the liquid per bridge from Eq. 5 with the particle mass
// (one V̂ for every pair), its viscous part; largest_radius (m) sets the range.
dem::CohesionLiquidBridge scene_bridge(const SlumpScene& s, double largest_radius);

std::string bridge_variant_name(const SlumpScene& s);  // mikami1998, yun-park-2017 or table
std::string wall_bridge_name(const SlumpScene& s);     // table or mikami1998

}  // namespace demscale::slump
