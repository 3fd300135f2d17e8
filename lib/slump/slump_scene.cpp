#include "slump/slump_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

#include "bridge/curve_sources.hpp"
#include "dem/bridge_law.hpp"
#include "core/input_error.hpp"
#include "io/toml_reader.hpp"
#include "dem/law_parts.hpp"

namespace demscale::slump {

namespace {
// The keys a scene may hold: the geometry and protocol's, the law selection's, and every
// registered law part's parameters (their tables, dem/law_parts.hpp).
std::map<std::string, std::vector<std::string_view>> scene_schema(std::span<const dem::LawPart> parts) {
    std::map<std::string, std::vector<std::string_view>> schema = {
        {"scene", {"name"}},
        {"cone", {"bottom_diameter_mm", "top_diameter_mm", "height_mm", "lift_speed_m_per_s", "lift_height_mm"}},
        {"particles", {"radius_mm", "density_kg_per_m3", "fill_height_mm", "fill_solid_fraction", "seed", "fill", "distribution",
                       "class_radii_mm", "mass_fractions", "median_radius_mm", "geometric_sd", "mass_quantiles"}},
        {"floor", {"rough", "rough_diameter_mm"}},
        {"contact", {"rolling_resistance", "rolling_model"}},
        {"liquid", {"wet", "wet_walls", "bridge_variant", "wall_bridge", "rupture", "lubrication"}},
        {"run", {"dt_s", "gravity_m_per_s2", "settle_time_s", "spread_time_s", "pour_time_s", "rest_speed_m_per_s",
                 "rest_duration_s", "rest_quantile", "skin_mm"}},
        {"check", {"slump_tolerance", "spread_tolerance", "profile_tolerance", "min_opening_diameters", "min_fill_diameters", "min_particles"}},
        {"similarity", {"scale_factors", "exponents"}},
    };
    auto add = [&](std::string_view key) {
        const auto dot = key.find('.');
        auto& names = schema[std::string(key.substr(0, dot))];
        if (std::find(names.begin(), names.end(), key.substr(dot + 1)) == names.end()) names.push_back(key.substr(dot + 1));
    };
    for (const auto& part : parts) {
        if (!part.choice.empty() && !dem::slot_key(part.slot).empty()) add(dem::slot_key(part.slot));
        for (const auto& p : part.parameters) add(p.key);
    }
    return schema;
}
void positive(double x, const std::string& f) { require_positive(x, f); }
}  // namespace

double bridge_vhat(const SlumpScene& s) { return dem::bridge_vhat(s, s.radius_m); }

double cone_radius_at(const SlumpScene& s, double z) {
    return 0.5 * s.bottom_diameter_m - 0.5 * (s.bottom_diameter_m - s.top_diameter_m) * z / s.height_m;
}

double cone_volume_below(const SlumpScene& s, double z) {  // frustum: π z (r₀² + r₀ r_z + r_z²) / 3
    const double r0 = cone_radius_at(s, 0), rz = cone_radius_at(s, z);
    return M_PI * z * (r0 * r0 + r0 * rz + rz * rz) / 3;
}

double smallest_radius(const SlumpScene& s) { return s.radius_m * s.sizes.smallest_ratio(); }
double largest_radius(const SlumpScene& s) { return s.radius_m * s.sizes.largest_ratio(); }

double fill_mass(const SlumpScene& s) { return s.material.density * s.fill_solid_fraction * cone_volume_below(s, s.fill_height_m); }

namespace {

constexpr double mm = 1e-3;

// The sizes: particles.radius_mm (one radius), or particles.distribution = "sieve" (class_radii_mm,
// mass_fractions) or "lognormal" (median_radius_mm, geometric_sd, mass_quantiles).
void read_sizes(const io::TomlReader& r, SlumpScene& s) {
    const std::string kind = r.text("particles.distribution").value_or("one_radius");
    auto where = [&](const std::string& key) { return r.where(key, key); };
    auto refuse_other = [&](std::initializer_list<const char*> keys, const std::string& why) {
        for (const char* key : keys)
            if (r.has(key))
                throw InputError(where(key), "given", "absent with particles.distribution = \"" + kind + "\" (" + why + ")");
    };
    if (kind == "one_radius") {
        refuse_other({"particles.class_radii_mm", "particles.mass_fractions", "particles.median_radius_mm", "particles.geometric_sd",
                      "particles.mass_quantiles"},
                     "one radius: particles.radius_mm");
        s.radius_m = r.checked("particles.radius_mm", 1.0, positive) * mm;
        return;
    }
    if (kind == "sieve") {
        refuse_other({"particles.radius_mm", "particles.median_radius_mm", "particles.geometric_sd", "particles.mass_quantiles"},
                     "a sieve table: class_radii_mm and mass_fractions");
        const auto radii = r.numbers("particles.class_radii_mm"), fractions = r.numbers("particles.mass_fractions");
        if (!radii || radii->empty() || radii->size() > max_size_classes)
            throw InputError(where("particles.class_radii_mm"), radii ? std::to_string(radii->size()) + " classes" : "missing",
                             "1 to " + std::to_string(max_size_classes) + " class radii, mm, ascending (one class: one radius)");
        if (!fractions || fractions->size() != radii->size())
            throw InputError(where("particles.mass_fractions"), fractions ? std::to_string(fractions->size()) + " numbers" : "missing",
                             "one mass fraction per class radius (" + std::to_string(radii->size()) + ")");
        double sum = 0;
        for (std::size_t c = 0; c < radii->size(); ++c) {
            const double x = (*radii)[c], f = (*fractions)[c];
            if (!(x > 0 && std::isfinite(x)) || (c > 0 && !(x > (*radii)[c - 1])))
                throw InputError(where("particles.class_radii_mm"), format_number(x), "radii > 0, mm, strictly ascending");
            if (!(f > 0 && f <= 1)) throw InputError(where("particles.mass_fractions"), format_number(f), "(0, 1] for every class");
            sum += f;
        }
        if (!(std::abs(sum - 1) <= 1e-3))
            throw InputError(where("particles.mass_fractions"), "sum " + format_number(sum), "fractions of the mass that sum to 1 (within 0.001)");
        // R is the mass median: the first class at which the cumulative mass reaches one half.
        double below = 0;
        std::size_t median = 0;
        while (below + (*fractions)[median] / sum < 0.5) below += (*fractions)[median++] / sum;
        s.radius_m = (*radii)[median] * mm;
        if (radii->size() == 1) return;  // one class: one radius, stored as such
        for (std::size_t c = 0; c < radii->size(); ++c) {
            s.sizes.class_ratios.push_back((*radii)[c] / (*radii)[median]);
            s.sizes.mass_fractions.push_back((*fractions)[c] / sum);
        }
        return;
    }
    if (kind == "lognormal") {
        refuse_other({"particles.radius_mm", "particles.class_radii_mm", "particles.mass_fractions"},
                     "a lognormal: median_radius_mm, geometric_sd, mass_quantiles");
        if (!r.number("particles.median_radius_mm"))
            throw InputError(where("particles.median_radius_mm"), "missing", "the mass-median radius, mm, > 0");
        s.radius_m = r.checked("particles.median_radius_mm", 1.0, positive) * mm;
        s.sizes.geometric_sd = r.checked("particles.geometric_sd", 1.3, [](double x, const std::string& f) {
            if (!(x >= 1 && x <= 3)) throw InputError(f, format_number(x), "[1, 3] (1: one radius)");
        });
        if (const auto q = r.numbers("particles.mass_quantiles")) {
            if (q->size() != 2 || !((*q)[0] >= 0.001 && (*q)[0] < 0.5 && (*q)[1] > 0.5 && (*q)[1] <= 0.999))
                throw InputError(where("particles.mass_quantiles"), std::to_string(q->size()) + " numbers",
                                 "[lower, upper] with 0.001 <= lower < 0.5 < upper <= 0.999 (where the mass distribution is cut)");
            s.sizes.lower_quantile = (*q)[0], s.sizes.upper_quantile = (*q)[1];
        }
        return;
    }
    throw InputError(where("particles.distribution"), "\"" + kind + "\"", "\"one_radius\", \"sieve\" or \"lognormal\"");
}

// [scene], [cone], [particles], [floor].
void read_geometry_and_fill(const io::TomlReader& r, SlumpScene& s) {
    if (auto n = r.text("scene.name")) s.name = *n;
    s.bottom_diameter_m = r.checked("cone.bottom_diameter_mm", 38, positive) * mm;
    s.top_diameter_m = r.checked("cone.top_diameter_mm", 19, positive) * mm;
    s.height_m = r.checked("cone.height_mm", 57, positive) * mm;
    s.lift_speed_m_per_s = r.checked("cone.lift_speed_m_per_s", 0.3, positive);
    s.lift_height_m = r.checked("cone.lift_height_mm", 65, positive) * mm;

    read_sizes(r, s);
    s.material.density = r.checked("particles.density_kg_per_m3", 2200, positive);
    s.fill_height_m = r.checked("particles.fill_height_mm", 54, positive) * mm;
    s.fill_solid_fraction = r.checked("particles.fill_solid_fraction", 0.5, [](double x, const std::string& f) {
        if (!(x >= 0.2 && x <= 0.64)) throw InputError(f, format_number(x), "[0.2, 0.64] (a poured fill's solid fraction, loose to random close)");
    });
    s.seed = static_cast<unsigned>(r.checked("particles.seed", 1, [](double x, const std::string& f) {
        if (!(x >= 0 && x < 4294967296.0 && std::floor(x) == x)) throw InputError(f, format_number(x), "an integer in [0, 2^32)");
    }));

    if (auto f = r.text("particles.fill")) {
        if (*f == "poured") s.fill = FillKind::poured;
        else if (*f == "lattice") s.fill = FillKind::lattice;
        else throw InputError(r.where("particles.fill", "particles.fill"), *f, "\"poured\" or \"lattice\"");
        if (s.fill == FillKind::lattice && !s.sizes.monodisperse())
            throw InputError(r.where("particles.fill", "particles.fill"), *f, "\"poured\" for a size distribution (a lattice holds one radius)");
    }

    s.rough_floor = r.boolean("floor.rough").value_or(false);
    s.rough_floor_diameter_m = r.checked("floor.rough_diameter_mm", 150, positive) * mm;
}

// Which laws the scene chooses: the rolling model, wet or dry, the bridge curves, lubrication, rupture.
void read_law_choices(const io::TomlReader& r, SlumpScene& s) {
    s.rolling_resistance = r.boolean("contact.rolling_resistance").value_or(true);
    if (auto m = r.text("contact.rolling_model")) {
        if (*m == "epsd") s.rolling_model = RollingModel::epsd;
        else if (*m == "epsd2") s.rolling_model = RollingModel::epsd2;
        else if (*m == "constant_torque") s.rolling_model = RollingModel::constant_torque;
        else throw InputError(r.where("contact.rolling_model", "contact.rolling_model"), *m, "\"epsd\", \"epsd2\" or \"constant_torque\"");
    }
    s.wet = r.boolean("liquid.wet").value_or(true);
    s.wet_walls = r.boolean("liquid.wet_walls").value_or(false);
    // The bridge curves: any source of bridge/curve_sources.hpp that has the geometry.
    auto curve = [&](const std::string& key, bridge::BridgeGeometry geometry) -> const bridge::CurveSourceEntry* {
        const auto v = r.text(key);
        if (!v) return nullptr;
        if (const auto* e = bridge::find_curve_source(*v, geometry)) return e;
        throw InputError(r.where(key, key), "\"" + *v + "\"", "one of " + bridge::curve_source_values(geometry));
    };
    if (const auto* e = curve("liquid.bridge_variant", bridge::BridgeGeometry::sphere_sphere)) {
        s.particle_curve = e->source;
        if (e->source == bridge::CurveSource::fit) s.bridge.variant = e->fit_variant;
    }
    if (const auto* e = curve("liquid.wall_bridge", bridge::BridgeGeometry::sphere_wall)) s.wall_curve = e->source;
    if (auto v = r.text("liquid.lubrication")) {
        if (*v == "finite_volume") s.lubrication = dem::Lubrication::finite_volume;
        else if (*v == "unbounded") s.lubrication = dem::Lubrication::unbounded;
        else throw InputError(r.where("liquid.lubrication", "liquid.lubrication"), "\"" + *v + "\"",
                              "\"finite_volume\" (Pitois et al. 2000) or \"unbounded\" (LIGGGHTS' easo/capillary/viscous)");
    }
    if (auto v = r.text("liquid.rupture"))
        r.check("liquid.rupture", [&] { s.bridge.rupture = bridge::parse_rupture_law(*v, "liquid.rupture"); });
}

// The law of each slot that a key chooses (contact.normal_law): one of its registered parts' choices.
void read_slot_choices(const io::TomlReader& r, SlumpScene& s, std::span<const dem::LawPart> parts) {
    for (const auto slot : {dem::Slot::normal, dem::Slot::tangential, dem::Slot::rolling, dem::Slot::cohesion}) {
        const std::string key(dem::slot_key(slot));
        const auto value = key.empty() ? std::nullopt : r.text(key);
        if (!value) continue;
        std::string accepted;
        for (const auto& part : parts)
            if (part.slot == slot && !part.choice.empty()) {
                if (part.choice == *value) {
                    part.choose(s);
                    accepted.clear();
                    break;
                }
                accepted += (accepted.empty() ? "\"" : ", \"") + std::string(part.choice) + "\"";
            }
        if (!accepted.empty()) throw InputError(r.where(key, key), "\"" + *value + "\"", "one of " + accepted);
    }
}

// Every registered part's parameters from its table, then what this scene's choices rule out.
void read_law_parameters(const io::TomlReader& r, SlumpScene& s, std::span<const dem::LawPart> parts) {
    for (const auto& part : parts)
        for (const auto& p : part.parameters) {
            const std::string key(p.key);
            p.set(s, r.checked(key, p.default_value, [&](double x, const std::string& f) {
                if (!p.accepted.contains(x))
                    throw InputError(f, format_number(x), p.accepted.text() + (p.unit == "1" ? "" : " " + std::string(p.unit)));
            }));
        }
    // A part whose parameters this scene cannot use (SJKR adhesion in a wet scene) is refused.
    for (const auto& part : parts)
        if (part.allowed && !part.allowed(s))
            for (const auto& p : part.parameters)
                if (p.get(s) != p.default_value) {
                    const std::string key(p.key);
                    throw InputError(r.where(key, key), format_number(p.get(s)), std::string(part.allowed_text));
                }
    // Ai et al.'s dashpot belongs to their model C (epsd); LIGGGHTS' epsd2 and cdt have none. Its
    // default 0.3 is Ai et al.'s own value: without the dashpot a sphere rocks on the rolling spring
    // with no loss, and a pile never comes to rest (docs/rest-and-damping.md).
    const bool dashpot = s.rolling_resistance && s.rolling_model == RollingModel::epsd;
    if (!dashpot) {
        if (r.number("contact.rolling_damping").value_or(0) > 0)
            throw InputError(r.where("contact.rolling_damping", "contact.rolling_damping"),
                             format_number(s.material.rolling_damping), "0 unless rolling_model = \"epsd\" (only Ai's model C has the dashpot)");
        s.material.rolling_damping = 0;
    }
}

// [run], [check], [similarity].
void read_run_and_check(const io::TomlReader& r, SlumpScene& s) {
    s.dt_s = r.checked("run.dt_s", 1e-5, positive);
    s.dt_field = r.where("run.dt_s", "run.dt_s");
    s.gravity = r.checked("run.gravity_m_per_s2", 9.81, positive);
    s.settle_time_s = r.checked("run.settle_time_s", 0.3, positive);
    s.spread_time_s = r.checked("run.spread_time_s", 0.4, positive);
    s.pour_time_s = r.checked("run.pour_time_s", 0.3, positive);
    s.rest_speed_m_per_s = r.checked("run.rest_speed_m_per_s", 1e-3, positive);
    s.rest_duration_s = r.checked("run.rest_duration_s", 0.02, positive);
    s.rest_quantile = r.checked("run.rest_quantile", 0.99, [](double x, const std::string& f) {
        if (!(x >= 0.5 && x <= 1)) throw InputError(f, format_number(x), "[0.5, 1] (the share of spheres that must be slower)");
    });
    s.skin_m = r.checked("run.skin_mm", 0.3, positive) * mm;
    s.tolerances.slump = r.checked("check.slump_tolerance", 0.10, positive);
    s.tolerances.spread = r.checked("check.spread_tolerance", 0.10, positive);
    s.tolerances.profile = r.checked("check.profile_tolerance", 0.15, positive);
    auto at_least_one = [](double x, const std::string& f) {
        if (!(x >= 1 && x < 1e9)) throw InputError(f, format_number(x), "[1, 1e9)");
    };
    s.limits.opening_diameters = r.checked("check.min_opening_diameters", 4, at_least_one);
    s.limits.fill_diameters = r.checked("check.min_fill_diameters", 8, at_least_one);
    s.limits.particles = r.checked("check.min_particles", 200, at_least_one);
    auto number_list = [&](const std::string& key, std::vector<double>& out, double lo, double hi) {
        const auto xs = r.numbers(key);
        if (!xs) return;
        if (xs->empty()) throw InputError(r.where(key, key), "[]", "at least one number");
        for (double x : *xs) r.check(key, [&] { require_in_open_interval(x, lo, hi, key); });
        out = *xs;
    };
    number_list("similarity.scale_factors", s.table_scale_factors, 0, 100);
    number_list("similarity.exponents", s.exponents, -20, 20);
}

// Consistency: the particles must fit the cone; the fill must fit under its top.
void check_consistency(const io::TomlReader& r, const SlumpScene& s) {
    if (!(s.top_diameter_m < s.bottom_diameter_m))
        throw InputError(r.where("cone.top_diameter_mm", "cone.top_diameter_mm"), format_number(s.top_diameter_m / mm),
                         "< cone.bottom_diameter_mm (a cone narrowing upwards)");
    if (!(2 * s.radius_m < 0.5 * s.top_diameter_m))  // the fine reference; coarse runs may go further
        throw InputError(r.where("particles.radius_mm", "particles.radius_mm"), format_number(s.radius_m / mm),
                         "< " + format_number(s.top_diameter_m / mm / 4) + " mm (a quarter of the top opening)");
    if (!(2 * largest_radius(s) < s.top_diameter_m)) {
        const std::string key = s.sizes.sieve() ? "particles.class_radii_mm" : "particles.geometric_sd";
        throw InputError(r.where(key, key), "largest sphere " + format_short(largest_radius(s) / mm, 4) + " mm",
                         "spheres that pass the cone's top opening (radius < " + format_number(s.top_diameter_m / mm / 2) + " mm)");
    }
    // The liquid per bridge (Eq. 5, independent of R) must lie where each acting bridge curve holds.
    auto check_vhat = [&](const bridge::CurveSourceEntry& source) {
        const double vhat = bridge_vhat(s), vhat_per_moisture = vhat / s.liquid.moisture_content;
        if (!(vhat >= source.vhat_min && vhat <= source.vhat_max))
            throw InputError(r.where("liquid.moisture_content", "liquid.moisture_content"), format_number(s.liquid.moisture_content),
                             "[" + format_short(source.vhat_min / vhat_per_moisture, 3) + ", " +
                                 format_short(source.vhat_max / vhat_per_moisture, 3) + "] here: the liquid per bridge V/R^3 = " +
                                 format_short(vhat, 3) + " (Eq. 5) must lie in " + std::string(source.vhat_range_name) + " [" +
                                 format_short(source.vhat_min, 3) + ", " + format_short(source.vhat_max, 3) + "] (" +
                                 std::string(source.value) + ")");
    };
    if (s.wet) check_vhat(dem::particle_curve_source(s));
    if (s.wet && s.wet_walls) check_vhat(dem::wall_curve_source(s));
    if (s.rough_floor && !(s.rough_floor_diameter_m >= s.bottom_diameter_m))
        throw InputError(r.where("floor.rough_diameter_mm", "floor.rough_diameter_mm"), format_number(s.rough_floor_diameter_m / mm),
                         ">= cone.bottom_diameter_mm = " + format_number(s.bottom_diameter_m / mm) + " (the rough disc carries the fill)");
    if (!(s.fill_height_m <= s.height_m))
        throw InputError(r.where("particles.fill_height_mm", "particles.fill_height_mm"), format_number(s.fill_height_m / mm),
                         "<= cone.height_mm = " + format_number(s.height_m / mm));
}

}  // namespace

SlumpScene load_slump_scene(const std::string& path, std::span<const dem::LawPart> parts) {
    const io::TomlReader r(path, scene_schema(parts));
    SlumpScene s;
    s.source = path;
    read_geometry_and_fill(r, s);
    read_law_choices(r, s);  // before the parameters: which parts a scene may use depends on them
    read_slot_choices(r, s, parts);
    read_law_parameters(r, s, parts);
    read_run_and_check(r, s);
    check_consistency(r, s);
    return s;
}

}  // namespace demscale::slump
