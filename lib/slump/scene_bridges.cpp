#include "slump/scene_bridges.hpp"

#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

#include "core/input_error.hpp"

namespace demscale::slump {

namespace {

// field: the scene key that chose the exact curve; fallback: the fit a user may choose instead.
bridge::BridgeCurve shared_exact_curve(const SlumpScene& s, bridge::BridgeGeometry geometry, const std::string& field,
                                       const std::string& fallback) {
    static std::mutex lock;
    static std::map<std::tuple<double, double, int>, bridge::BridgeCurve> solved;
    const double vhat = bridge_vhat(s), theta = s.liquid.contact_angle.radians();
    const std::tuple key{vhat, theta, static_cast<int>(geometry)};
    const std::lock_guard guard(lock);
    if (const auto it = solved.find(key); it != solved.end()) return it->second;
    try {
        return solved.emplace(key, bridge::BridgeCurve::exact(vhat, s.liquid.contact_angle, geometry)).first->second;
    } catch (const std::runtime_error& e) {
        throw InputError(s.source.empty() ? field : s.source + ": " + field, "\"table\" at V^ = " + format_short(vhat, 4) + ", theta = " + format_short(s.liquid.contact_angle.degrees(), 4) + " deg",
                         "a V^ and theta where the exact solver finds a concave bridge, or " + fallback + " (" + std::string(e.what()) + ")");
    }
}

}  // namespace

bridge::BridgeCurve particle_bridge_curve(const SlumpScene& s) {
    if (s.particle_curve == bridge::CurveSource::exact)
        return shared_exact_curve(s, bridge::BridgeGeometry::sphere_sphere, "liquid.bridge_variant", "bridge_variant = \"mikami1998\"");
    return bridge::mikami_coefficients(bridge_vhat(s), s.liquid.contact_angle, s.bridge);
}

bridge::BridgeCurve wall_bridge_curve(const SlumpScene& s) {
    if (s.wall_curve == bridge::CurveSource::exact)
        return shared_exact_curve(s, bridge::BridgeGeometry::sphere_wall, "liquid.wall_bridge", "wall_bridge = \"mikami1998\"");
    return bridge::mikami_coefficients(bridge_vhat(s), s.liquid.contact_angle, s.bridge, bridge::BridgeGeometry::sphere_wall);
}

dem::CohesionLiquidBridge scene_bridge(const SlumpScene& s, double largest_radius) {
    // The wall curve goes in through the constructor, which computes the contact forces from it.
    return {particle_bridge_curve(s), largest_radius, s.liquid.surface_tension_n_per_m,
            s.wet_walls ? std::optional(wall_bridge_curve(s)) : std::nullopt, s.viscosity_pa_s, s.min_gap_ratio * s.radius_m,
            s.lubrication, bridge_vhat(s)};
}

std::string bridge_variant_name(const SlumpScene& s) {
    return s.particle_curve == bridge::CurveSource::exact ? "table" : std::string(bridge::to_string(s.bridge.variant));
}

std::string wall_bridge_name(const SlumpScene& s) { return s.wall_curve == bridge::CurveSource::exact ? "table" : "mikami1998"; }

}  // namespace demscale::slump
