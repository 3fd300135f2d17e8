#include "slump/scene_bridges.hpp"

#include "dem/bridge_law.hpp"

namespace demscale::slump {

bridge::BridgeCurve particle_bridge_curve(const SlumpScene& s) {
    return dem::bridge_curve(dem::particle_curve_source(s), s, bridge_vhat(s), bridge::BridgeGeometry::sphere_sphere, "liquid.bridge_variant", s.source);
}

bridge::BridgeCurve wall_bridge_curve(const SlumpScene& s) {
    return dem::bridge_curve(dem::wall_curve_source(s), s, bridge_vhat(s), bridge::BridgeGeometry::sphere_wall, "liquid.wall_bridge", s.source);
}

dem::CohesionLiquidBridge scene_bridge(const SlumpScene& s, double largest_radius) {
    return dem::build_liquid_bridge<dem::BridgeRadius::common>(s, s.radius_m, largest_radius, bridge_vhat(s), s.source);
}

std::string bridge_variant_name(const SlumpScene& s) { return std::string(dem::particle_curve_source(s).value); }

std::string wall_bridge_name(const SlumpScene& s) { return std::string(dem::wall_curve_source(s).value); }

}  // namespace demscale::slump
