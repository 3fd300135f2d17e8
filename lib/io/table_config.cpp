#include "io/table_config.hpp"

#include <cmath>

#include "core/input_error.hpp"
#include "io/toml_reader.hpp"

namespace demscale::io {

namespace {
const std::map<std::string, std::vector<std::string_view>> schema = {
    {"particle", {"physical_radius_mm", "radii_mm", "masses_g", "mass_resolution_g", "density_kg_per_m3", "mass_source"}},
    {"liquid", {"surface_tension_n_per_m", "contact_angle_deg", "density_kg_per_m3", "moisture_content"}},
    {"bridge", {"variant", "rupture"}},
    {"similarity", {"exponents"}},
    {"curves", {"hhat_max", "points"}},
};

void positive(double x, const std::string& field) { require_positive(x, field); }

// Each element of an array positive; the error names the element.
std::vector<double> positive_array(const TomlReader& r, const std::string& dotted, double scale) {
    std::vector<double> out;
    const std::vector<double> values = r.numbers(dotted).value_or(std::vector<double>{});
    for (const double x : values) {
        r.check(dotted, [&] { require_positive(x, dotted + "[" + std::to_string(out.size()) + "]"); });
        out.push_back(x * scale);
    }
    return out;
}
}  // namespace

TableConfig load_table_config(const std::string& path) {
    const TomlReader r(path, schema);
    TableConfig c;
    c.source = path;
    constexpr double mm = 1e-3, g = 1e-3;

    c.physical_radius_m = r.checked("particle.physical_radius_mm", 1.0, positive) * mm;
    const auto radii = r.numbers("particle.radii_mm");
    if (!radii || radii->empty())
        throw InputError(path + ": particle.radii_mm", "(missing)", "a non-empty array of radii in mm");
    c.radii_m = positive_array(r, "particle.radii_mm", mm);
    if (r.numbers("particle.masses_g")) {
        c.tabulated_masses_kg = positive_array(r, "particle.masses_g", g);
        if (c.tabulated_masses_kg.size() != c.radii_m.size())
            throw InputError(path + ": particle.masses_g", std::to_string(c.tabulated_masses_kg.size()) + " values",
                             std::to_string(c.radii_m.size()) + " values, one per radius");
    }
    c.mass_resolution_kg = r.checked("particle.mass_resolution_g", 0.01, positive) * g;
    if (r.number("particle.density_kg_per_m3"))
        c.solid_density_kg_per_m3 = r.checked("particle.density_kg_per_m3", 0.0, positive);
    if (auto s = r.text("particle.mass_source")) {
        if (*s == "density") c.mass_source = MassSource::density;
        else if (*s == "table") c.mass_source = MassSource::table;
        else r.check("particle.mass_source", [&] {
            throw InputError("particle.mass_source", "\"" + *s + "\"", "one of density, table");
        });
    }
    if (c.tabulated_masses_kg.empty() && (c.mass_source == MassSource::table || !c.solid_density_kg_per_m3))
        throw InputError(path + ": particle.masses_g", "(missing)",
                         "masses_g (needed by mass_source = \"table\" or when density_kg_per_m3 is absent)");

    c.liquid.surface_tension_n_per_m = r.checked("liquid.surface_tension_n_per_m", 0.074, positive);
    if (auto x = r.number("liquid.contact_angle_deg"))
        r.check("liquid.contact_angle_deg", [&] { c.liquid.contact_angle = ContactAngle(Degrees{*x}); });
    c.liquid.density_kg_per_m3 = r.checked("liquid.density_kg_per_m3", 1000.0, positive);
    c.liquid.moisture_content = r.checked("liquid.moisture_content", 0.045, [](double x, const std::string& f) {
        require_in_open_interval(x, 0.0, 1.0, f);
    });
    if (auto s = r.text("bridge.variant"))
        r.check("bridge.variant", [&] { c.bridge.variant = bridge::parse_mikami_variant(*s, "bridge.variant"); });
    if (auto s = r.text("bridge.rupture"))
        r.check("bridge.rupture", [&] { c.bridge.rupture = bridge::parse_rupture_law(*s, "bridge.rupture"); });

    if (auto ks = r.numbers("similarity.exponents")) {
        if (ks->empty()) throw InputError(path + ": similarity.exponents", "[]", "at least one exponent");
        for (double k : *ks)
            r.check("similarity.exponents", [&] { require_in_open_interval(k, -20.0, 20.0, "similarity.exponents"); });
        c.exponents = *ks;
    }
    c.curve_hhat_max = r.checked("curves.hhat_max", 0.5, [](double x, const std::string& f) {
        require_in_open_interval(x, 0.0, 100.0, f);
    });
    c.curve_points = static_cast<int>(r.checked("curves.points", 101, [](double x, const std::string& f) {
        if (!(x >= 2 && x <= 100000 && std::floor(x) == x)) throw InputError(f, format_number(x), "an integer in [2, 100000]");
    }));
    return c;
}

}  // namespace demscale::io
