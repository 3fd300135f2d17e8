#include "dem/bridge_law.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

#include "bridge/liquid_volume.hpp"
#include "core/input_error.hpp"

namespace demscale::dem {

const bridge::CurveSourceEntry& particle_curve_source(const ContactSettings& s) {
    return bridge::curve_source(s.particle_curve, s.bridge.variant, bridge::BridgeGeometry::sphere_sphere);
}

const bridge::CurveSourceEntry& wall_curve_source(const ContactSettings& s) {
    return bridge::curve_source(s.wall_curve, s.bridge.variant, bridge::BridgeGeometry::sphere_wall);
}

bridge::BridgeCurve bridge_curve(const bridge::CurveSourceEntry& source, const ContactSettings& s, double vhat, bridge::BridgeGeometry geometry,
                                 const std::string& field, const std::string& where) {
    static std::mutex lock;
    static std::map<std::tuple<const bridge::CurveSourceEntry*, double, double, int, int, int>, bridge::BridgeCurve> built;
    const ContactAngle theta = s.liquid.contact_angle;
    const std::tuple key{&source, vhat, theta.radians(), static_cast<int>(geometry), static_cast<int>(s.bridge.variant),
                         static_cast<int>(s.bridge.rupture)};
    const std::lock_guard guard(lock);
    if (const auto it = built.find(key); it != built.end()) return it->second;
    try {
        return built.emplace(key, source.build(vhat, theta, geometry, s.bridge)).first->second;
    } catch (const std::runtime_error& e) {
        throw InputError(where.empty() ? field : where + ": " + field,
                         "\"" + std::string(source.value) + "\" at V^ = " + format_short(vhat, 4) + ", theta = " + format_short(theta.degrees(), 4) + " deg",
                         "a V^ and theta where it has a concave bridge, or " + field.substr(field.find('.') + 1) +
                             " = \"mikami1998\" (" + std::string(e.what()) + ")");  // the fit has a bridge everywhere
    }
}

template <BridgeRadius Radius>
LiquidBridge<Radius> build_liquid_bridge(const ContactSettings& s, double radius_m, double largest_radius_m, double vhat, const std::string& where) {
    auto particle = bridge_curve(particle_curve_source(s), s, vhat, bridge::BridgeGeometry::sphere_sphere, "liquid.bridge_variant", where);
    // The wall curve goes in through the constructor, which computes the contact forces from it.
    auto wall = s.wet_walls ? std::optional(bridge_curve(wall_curve_source(s), s, vhat, bridge::BridgeGeometry::sphere_wall, "liquid.wall_bridge", where))
                            : std::nullopt;
    return {std::move(particle), largest_radius_m, s.liquid.surface_tension_n_per_m, std::move(wall), s.viscosity_pa_s, s.min_gap_ratio * radius_m, s.lubrication, vhat};
}
template CohesionLiquidBridge build_liquid_bridge<BridgeRadius::common>(const ContactSettings&, double, double, double, const std::string&);
template CohesionLiquidBridgePerPair build_liquid_bridge<BridgeRadius::per_pair>(const ContactSettings&, double, double, double, const std::string&);

double bridge_vhat(const ContactSettings& s, double radius_m) {
    const double mass = s.material.density * 4.0 / 3.0 * M_PI * std::pow(radius_m, 3);
    return bridge::liquid_bridge_volume(s.liquid.moisture_content, mass, s.liquid.density_kg_per_m3) / std::pow(radius_m, 3);
}

template <BridgeRadius Radius>
LiquidBridge<Radius> LiquidBridge<Radius>::build(const ContactSettings& s, const LawSizes& sizes, const std::string& where) {
    return build_liquid_bridge<Radius>(s, sizes.radius_m, sizes.largest_radius_m, bridge_vhat(s, sizes.radius_m), where);
}
template CohesionLiquidBridge CohesionLiquidBridge::build(const ContactSettings&, const LawSizes&, const std::string&);
template CohesionLiquidBridgePerPair CohesionLiquidBridgePerPair::build(const ContactSettings&, const LawSizes&, const std::string&);

}  // namespace demscale::dem
