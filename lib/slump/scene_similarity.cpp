#include "slump/scene_similarity.hpp"

#include <cmath>

#include "core/input_error.hpp"
#include "dem/law_parts.hpp"
#include "slump/scene_bridges.hpp"

namespace demscale::slump {

io::TableConfig similarity_inputs(const SlumpScene& s) {
    io::TableConfig c;
    c.source = s.source;
    c.physical_radius_m = s.radius_m;
    for (double sf : s.table_scale_factors) c.radii_m.push_back(sf * s.radius_m);
    c.solid_density_kg_per_m3 = s.material.density;
    c.mass_source = io::MassSource::density;
    c.liquid = s.liquid;
    c.bridge = s.bridge;
    c.exponents = s.exponents;
    if (!s.sizes.monodisperse())
        c.sizes_note = "sizes: " + describe(s.sizes) +
                       ". The rows are at the mass-median radius R; every size scales by S_f alike, so each ratio (a power of S_f) "
                       "holds for every size, and for a bridge between unequal spheres, whose R* = 2 R1 R2 / (R1 + R2) scales by S_f too";
    return c;
}

std::vector<std::string> differing_inputs(const io::TableConfig& c, const SlumpScene& s) {
    std::vector<std::string> out;
    auto differ = [&](const std::string& config_key, const std::string& config, const std::string& scene_key, const std::string& scene) {
        out.push_back(config_key + " = " + config + " in the config, " + scene_key + " = " + scene + " in the scene");
    };
    auto compare = [&](const std::string& config_key, const std::string& scene_key, double config, double scene, double unit) {
        if (std::abs(config - scene) > 1e-12 * std::max(std::abs(config), std::abs(scene)))
            differ(config_key, format_number(config / unit), scene_key, format_number(scene / unit));
    };
    auto compare_name = [&](const std::string& config_key, const std::string& scene_key, std::string_view config, std::string_view scene) {
        if (config != scene) differ(config_key, std::string(config), scene_key, std::string(scene));
    };
    compare("particle.physical_radius_mm", "particles.radius_mm", c.physical_radius_m, s.radius_m, 1e-3);
    if (c.solid_density_kg_per_m3)
        compare("particle.density_kg_per_m3", "particles.density_kg_per_m3", *c.solid_density_kg_per_m3, s.material.density, 1);
    // The liquid as the bridge's parameter table reads it: the same keys in both files.
    dem::ContactSettings configured;
    configured.liquid = c.liquid;
    for (const auto& p : dem::bridge_parameters) compare(std::string(p.key), std::string(p.key), p.get(configured), p.get(s), 1);
    compare_name("bridge.variant", "liquid.bridge_variant", bridge::to_string(c.bridge.variant), bridge_variant_name(s));
    if (s.particle_curve == bridge::CurveSource::fit)  // the exact bridge has its own rupture
        compare_name("bridge.rupture", "liquid.rupture", bridge::to_string(c.bridge.rupture), bridge::to_string(s.bridge.rupture));
    return out;
}

}  // namespace demscale::slump
