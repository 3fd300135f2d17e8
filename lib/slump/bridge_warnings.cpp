#include "slump/bridge_warnings.hpp"

#include "bridge/mikami.hpp"
#include "bridge/validity.hpp"
#include "bridge/young_laplace.hpp"
#include "core/input_error.hpp"
#include "slump/scene_bridges.hpp"

namespace demscale::slump {

std::vector<std::string> bridge_warnings(const SlumpScene& s) {
    std::vector<std::string> out;
    if (!s.wet) return out;
    const double vhat = bridge_vhat(s);
    const ContactAngle theta = s.liquid.contact_angle;
    // A tabulated curve (exact, Willett's) has no Mikami range; building it here refuses a scene
    // where it has no bridge.
    if (s.particle_curve != bridge::CurveSource::fit) particle_bridge_curve(s);
    else
        for (const auto& w : bridge::check_validity(vhat, theta, bridge::mikami_coefficients(vhat, theta, s.bridge)))
            out.push_back("particle-particle bridges (" + bridge_variant_name(s) + "): " + w.message);
    if (!s.wet_walls) return out;
    if (s.wall_curve != bridge::CurveSource::fit) {
        wall_bridge_curve(s);
        return out;
    }
    const auto wall = bridge::mikami_coefficients(vhat, theta, s.bridge, bridge::BridgeGeometry::sphere_wall);
    for (const auto& w : bridge::check_validity(vhat, theta, wall)) out.push_back("particle-wall bridges (Mikami's sphere-wall fit): " + w.message);
    const auto exact = bridge::YoungLaplaceBridge::sphere_plane(vhat, theta, theta).solve(0.0);
    if (exact.ok()) {
        const double fit = bridge::f_over_2pi_r_gamma(wall, bridge::mikami_fhat(wall, 0.0));
        out.push_back("particle-wall bridges: Mikami's sphere-wall fit pulls " + format_short(100 * (fit / exact.shape.fhat_neck - 1), 3) +
                      " % harder at contact than the exact sphere-plane bridge (V^ = " + format_short(vhat, 4) +
                      ", theta = " + format_short(theta.degrees(), 3) + " deg; docs/bridge-models.md)");
    }
    return out;
}

}  // namespace demscale::slump
