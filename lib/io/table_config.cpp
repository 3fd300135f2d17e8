#include "io/table_config.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <toml++/toml.h>

#include "core/input_error.hpp"
#include "core/nearest_name.hpp"

namespace demscale::io {

namespace {

// Field name with file and line, as every config error message starts.
std::string where(const std::string& path, const toml::node* node, const std::string& key) {
    std::string s = path;
    if (node && node->source().begin.line > 0) s += ":" + std::to_string(node->source().begin.line);
    return s + ": " + key;
}

const std::map<std::string, std::vector<std::string_view>> allowed_keys = {
    {"particle", {"physical_radius_mm", "radii_mm", "masses_g", "mass_resolution_g", "density_kg_per_m3",
                  "mass_source"}},
    {"liquid", {"surface_tension_n_per_m", "contact_angle_deg", "density_kg_per_m3", "moisture_content"}},
    {"bridge", {"variant", "rupture"}},
    {"similarity", {"exponents"}},
    {"curves", {"hhat_max", "points"}},
};

void reject_unknown_keys(const toml::table& root, const std::string& path) {
    std::vector<std::string_view> sections;
    for (const auto& [name, keys] : allowed_keys) sections.push_back(name);
    for (const auto& [key, node] : root) {
        const std::string section(key.str());
        auto it = allowed_keys.find(section);
        if (it == allowed_keys.end())
            throw InputError(where(path, &node, section), "(section)",
                             "a known section (did you mean [" + std::string(nearest_name(section, sections)) + "]?)");
        if (!node.is_table())
            throw InputError(where(path, &node, section), "(value)", "a [" + section + "] table");
        for (const auto& [sub, subnode] : *node.as_table()) {
            const std::string name(sub.str());
            if (std::find(it->second.begin(), it->second.end(), std::string_view(name)) == it->second.end())
                throw InputError(where(path, &subnode, section + "." + name), "(unknown key)",
                                 "a key of [" + section + "] (did you mean " + section + "." +
                                     std::string(nearest_name(name, it->second)) + "?)");
        }
    }
}

class Reader {
public:
    Reader(const toml::table& root, std::string path) : root_(root), path_(std::move(path)) {}

    std::optional<double> number(const std::string& dotted) const {
        const toml::node* n = root_.at_path(dotted).node();
        if (!n) return std::nullopt;
        if (auto v = n->value<double>()) {  // accepts integers too
            if (!std::isfinite(*v)) throw InputError(where(path_, n, dotted), format_number(*v), "a finite number");
            return *v;
        }
        throw InputError(where(path_, n, dotted), "(not a number)", "a number");
    }

    std::optional<std::string> text(const std::string& dotted) const {
        const toml::node* n = root_.at_path(dotted).node();
        if (!n) return std::nullopt;
        if (auto v = n->value<std::string>()) return *v;
        throw InputError(where(path_, n, dotted), "(not a string)", "a quoted string");
    }

    std::optional<std::vector<double>> numbers(const std::string& dotted) const {
        const toml::node* n = root_.at_path(dotted).node();
        if (!n) return std::nullopt;
        const toml::array* a = n->as_array();
        if (!a) throw InputError(where(path_, n, dotted), "(not an array)", "an array of numbers, e.g. [1.0, 2.0]");
        std::vector<double> out;
        for (std::size_t i = 0; i < a->size(); ++i) {
            auto v = (*a)[i].value<double>();
            const std::string item = dotted + "[" + std::to_string(i) + "]";
            if (!v) throw InputError(where(path_, &(*a)[i], item), "(not a number)", "a number");
            if (!std::isfinite(*v)) throw InputError(where(path_, &(*a)[i], item), format_number(*v), "a finite number");
            out.push_back(*v);
        }
        return out;
    }

    // Runs a validation and prefixes its error with file and line.
    template <class F>
    void check(const std::string& dotted, F&& validate) const {
        try {
            validate();
        } catch (const InputError& e) {
            const std::string field = e.field() == dotted || e.field().rfind(dotted, 0) == 0 ? e.field() : dotted;
            throw InputError(where(path_, root_.at_path(dotted).node(), field), e.value(), e.accepted());
        }
    }

private:
    const toml::table& root_;
    std::string path_;
};

}  // namespace

TableConfig load_table_config(const std::string& path) {
    if (!std::filesystem::exists(path)) throw InputError("--config", path, "an existing TOML file (not found)");
    toml::table root;
    try {
        root = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        throw InputError(path + ":" + std::to_string(e.source().begin.line) + ": (TOML syntax)",
                         std::string(e.description()), "well-formed TOML");
    }
    reject_unknown_keys(root, path);
    const Reader r(root, path);
    TableConfig c;
    c.source = path;

    const auto mm = [](double x) { return x * 1e-3; };
    const auto g = [](double x) { return x * 1e-3; };

    if (auto x = r.number("particle.physical_radius_mm")) {
        r.check("particle.physical_radius_mm", [&] { require_positive(*x, "particle.physical_radius_mm"); });
        c.physical_radius_m = mm(*x);
    }
    auto radii = r.numbers("particle.radii_mm");
    if (!radii || radii->empty())
        throw InputError(path + ": particle.radii_mm", "(missing)", "a non-empty array of radii in mm");
    for (std::size_t i = 0; i < radii->size(); ++i) {
        const std::string f = "particle.radii_mm[" + std::to_string(i) + "]";
        r.check("particle.radii_mm", [&] { require_positive((*radii)[i], f); });
        c.radii_m.push_back(mm((*radii)[i]));
    }
    if (auto masses = r.numbers("particle.masses_g")) {
        if (masses->size() != radii->size())
            throw InputError(path + ": particle.masses_g", std::to_string(masses->size()) + " values",
                             std::to_string(radii->size()) + " values, one per radius");
        for (std::size_t i = 0; i < masses->size(); ++i) {
            const std::string f = "particle.masses_g[" + std::to_string(i) + "]";
            r.check("particle.masses_g", [&] { require_positive((*masses)[i], f); });
            c.tabulated_masses_kg.push_back(g((*masses)[i]));
        }
    }
    if (auto x = r.number("particle.mass_resolution_g")) {
        r.check("particle.mass_resolution_g", [&] { require_positive(*x, "particle.mass_resolution_g"); });
        c.mass_resolution_kg = g(*x);
    }
    if (auto x = r.number("particle.density_kg_per_m3")) {
        r.check("particle.density_kg_per_m3", [&] { require_positive(*x, "particle.density_kg_per_m3"); });
        c.solid_density_kg_per_m3 = *x;
    }
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

    if (auto x = r.number("liquid.surface_tension_n_per_m")) {
        r.check("liquid.surface_tension_n_per_m", [&] { require_positive(*x, "liquid.surface_tension_n_per_m"); });
        c.liquid.surface_tension_n_per_m = *x;
    }
    if (auto x = r.number("liquid.contact_angle_deg")) {
        r.check("liquid.contact_angle_deg", [&] { c.liquid.contact_angle = ContactAngle(Degrees{*x}); });
    }
    if (auto x = r.number("liquid.density_kg_per_m3")) {
        r.check("liquid.density_kg_per_m3", [&] { require_positive(*x, "liquid.density_kg_per_m3"); });
        c.liquid.density_kg_per_m3 = *x;
    }
    if (auto x = r.number("liquid.moisture_content")) {
        r.check("liquid.moisture_content", [&] { require_in_open_interval(*x, 0.0, 1.0, "liquid.moisture_content"); });
        c.liquid.moisture_content = *x;
    }
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
    if (auto x = r.number("curves.hhat_max")) {
        r.check("curves.hhat_max", [&] { require_in_open_interval(*x, 0.0, 100.0, "curves.hhat_max"); });
        c.curve_hhat_max = *x;
    }
    if (auto x = r.number("curves.points")) {
        r.check("curves.points", [&] {
            if (!(*x >= 2 && *x <= 100000 && std::floor(*x) == *x))
                throw InputError("curves.points", format_number(*x), "an integer in [2, 100000]");
        });
        c.curve_points = static_cast<int>(*x);
    }
    return c;
}

}  // namespace demscale::io
