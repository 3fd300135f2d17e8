// The law parts' declarations: each table against independent sources (the struct defaults, the
// similarity catalogue's dimensions, a hand derivation of the viscous time step), and the promise
// that a parameter added to a table reaches the scene reader, the cache key and the report with no
// other edit; and the scene-file reference (docs/file-formats.md) quoting each default as the table has it.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <utility>

#include "bridge/curve_sources.hpp"
#include "core/input_error.hpp"
#include "dem/law_builder.hpp"
#include "dem/law_parts.hpp"
#include "report/scene_table.hpp"
#include "similarity/quantity_catalogue.hpp"
#include "slump/coarse_grain.hpp"
#include "slump/compiled_engines.hpp"
#include "slump/run_cache.hpp"
#include "slump/scene_text.hpp"
#include "slump/slump_run.hpp"
#include "slump/slump_scene.hpp"

using namespace demscale;
using namespace demscale::dem;

namespace {
std::string write_scene(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path) << text;
    return path.string();
}
}  // namespace

TEST_CASE("Every law parameter: default inside its range and equal to the settings' own default, keys unique",
          "[dem][parameters]") {
    const ContactSettings defaults;
    std::vector<std::string_view> keys;
    for (const auto& part : law_parts())
        for (const auto& p : part.parameters) {
            INFO(p.key);
            CHECK(p.accepted.contains(p.default_value));
            CHECK(p.get(defaults) == Approx(p.default_value).epsilon(1e-15));
            CHECK(std::count(keys.begin(), keys.end(), p.key) == 0);
            keys.push_back(p.key);
            CHECK((p.replacement != Replacement::scalable || !p.scale_name.empty()));
            // Setting and getting round-trips in the input unit (degrees for the contact angle).
            ContactSettings s;
            const double x = p.accepted.hi == unbounded ? 2 * p.default_value + 1 : 0.5 * (p.accepted.lo + p.accepted.hi);
            p.set(s, x);
            CHECK(p.get(s) == Approx(x).epsilon(1e-14));
        }
    CHECK(keys.size() == 14);
}

TEST_CASE("Law parameters carry the similarity catalogue's dimensions", "[dem][parameters][similarity]") {
    const std::pair<std::string_view, std::string_view> same[] = {{"contact.youngs_modulus_pa", "youngs_modulus"},
                                                                   {"liquid.surface_tension_n_per_m", "surface_tension"},
                                                                   {"liquid.viscosity_pa_s", "viscosity"}};
    for (const auto& [key, quantity] : same)
        for (const auto& part : law_parts())
            for (const auto& p : part.parameters)
                if (p.key == key) CHECK(p.dimension == similarity::find_quantity(quantity, "test").dimension);
}

TEST_CASE("The viscous bridge limits the step to 0.2 x 2 m*/c, derived by hand", "[dem][parameters][timestep]") {
    ContactSettings s;
    s.viscosity_pa_s = 0.5, s.min_gap_ratio = 0.01, s.material.density = 2200;
    const double r = 1e-3, m = 2200 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const double c = 6 * std::numbers::pi * 0.5 * (r / 2) * (r / 2) / (0.01 * r);  // 6π μ R*² / s_min
    const auto limits = time_step_limits(s, r);
    REQUIRE(limits.size() == 2);  // Hertz and the viscous part
    CHECK(limits[1].seconds == Approx(2 * (m / 2) / c).epsilon(1e-12));
    CHECK(limits[0].seconds == Approx(rayleigh_time(s.material, r)).epsilon(1e-15));
    s.viscosity_pa_s = 0;
    CHECK(time_step_limits(s, r).size() == 1);  // no viscous part, no limit of its own
    // A scene whose viscous limit binds is refused, naming it.
    slump::SlumpScene scene;
    scene.viscosity_pa_s = 0.5, scene.dt_s = 1e-5;  // 0.2 × 2m*/c = 3.9 µs here
    CHECK_THROWS_WITH(slump::check_slump_time_step(scene, false), Catch::Matchers::Contains("lubrication time"));
    CHECK_NOTHROW(slump::check_slump_time_step(scene, true));
}

TEST_CASE("Coarse-graining follows each table's rule: gamma S_f^k, E and mu by their dimensions when named",
          "[dem][parameters][coarse]") {
    slump::SlumpScene fine;
    fine.viscosity_pa_s = 1e-3;
    const double sf = 1.96;
    for (double k : {1.0, 2.0, 3.0}) {
        // S_L = S_f, S_ρ = 1 and γ ∝ ρ L³ T⁻² give S_T = S_f^((3−k)/2): E ∝ ρ L² T⁻² needs S_f^(k−1),
        // μ ∝ ρ L² T⁻¹ needs S_f^((1+k)/2).
        const auto c = slump::coarse_grained(fine, {sf, k, {"youngs_modulus", "viscosity"}});
        CHECK(c.liquid.surface_tension_n_per_m == Approx(0.074 * std::pow(sf, k)).epsilon(1e-14));
        CHECK(c.material.youngs_modulus == Approx(5e6 * std::pow(sf, k - 1)).epsilon(1e-12));
        CHECK(c.viscosity_pa_s == Approx(1e-3 * std::pow(sf, (1 + k) / 2)).epsilon(1e-12));
        CHECK(c.material.friction == fine.material.friction);
        CHECK(c.liquid.moisture_content == fine.liquid.moisture_content);
    }
}

TEST_CASE("A parameter added to a law's table reaches the scene reader, the cache key and the report", "[dem][parameters]") {
    // A part that declares one parameter, stored where no acting part looks (the linear law's k,
    // which Hertz scenes do not read).
    static constexpr Parameter extra[] = {
        {"contact.test_stiffness_n_per_m", "test spring stiffness k", "N/m", {3, 1, -2}, 100, {0, unbounded},
         Replacement::kept, {}, {}, LiggghtsKind::scalar, [](const ContactSettings& s) { return s.material.linear_stiffness; },
         [](ContactSettings& s, double x) { s.material.linear_stiffness = x; }}};
    static constexpr LawPart part{"test part", extra, [](const ContactSettings&) { return true; }};
    std::vector<LawPart> parts(law_parts().begin(), law_parts().end());
    parts.push_back(part);

    const auto path = write_scene("demscale_extra_parameter.toml", "[contact]\ntest_stiffness_n_per_m = 1234\n");
    // The reader knows the key only through the table.
    CHECK_THROWS_WITH(slump::load_slump_scene(path), Catch::Matchers::Contains("test_stiffness_n_per_m"));
    const auto s = slump::load_slump_scene(path, parts);
    CHECK(s.material.linear_stiffness == 1234);
    CHECK(slump::load_slump_scene(write_scene("demscale_no_extra.toml", "[scene]\n"), parts).material.linear_stiffness == 100);
    CHECK_THROWS_WITH(slump::load_slump_scene(write_scene("demscale_bad_extra.toml", "[contact]\ntest_stiffness_n_per_m = -1\n"),
                                              parts),
                      Catch::Matchers::Contains("test_stiffness_n_per_m = -1: accepted a finite number > 0 N/m"));
    // The cache key follows its value.
    auto t = s;
    CHECK(slump::scene_key(s, parts) == slump::scene_key(t, parts));
    t.material.linear_stiffness = 1235;
    CHECK(slump::scene_key(s, parts) != slump::scene_key(t, parts));
    CHECK(slump::scene_key(s) == slump::scene_key(t));  // without the part, the value is not an input
    // The report lists it with its unit.
    const auto table = report::scene_table(s, "test", parts);
    bool listed = false;
    for (const auto& row : table.rows)
        if (std::get<std::string>(row[0]) == "test spring stiffness k")
            listed = std::get<double>(row[1]) == 1234 && std::get<std::string>(row[2]) == "N/m";
    CHECK(listed);
}

TEST_CASE("docs/file-formats.md lists every law parameter with the default its table declares", "[dem][parameters][docs]") {
    std::ifstream in(std::string(DEMSCALE_SOURCE_DIR) + "/docs/file-formats.md");
    REQUIRE(in);
    std::string line, page;
    while (std::getline(in, line)) page += line + "\n";
    for (const auto& part : law_parts())
        for (const auto& p : part.parameters) {
            INFO(p.key);
            // | `contact.rolling_damping` | 1 | 0.3 (epsd), else 0 | ...: the third cell starts with the default.
            const auto row = page.find("| `" + std::string(p.key) + "` |");
            REQUIRE(row != std::string::npos);
            const auto cells = page.substr(row, page.find('\n', row) - row);
            std::size_t bar = 0;
            for (int i = 0; i < 2; ++i) bar = cells.find('|', bar + 1);  // past the key and the unit
            const std::string quoted = cells.substr(bar + 1);
            char* end = nullptr;
            const double documented = std::strtod(quoted.c_str(), &end);
            INFO("documented: " << quoted.substr(0, quoted.find('|')));
            REQUIRE(end != quoted.c_str());
            CHECK(documented == Approx(p.default_value).epsilon(1e-12).margin(1e-300));
        }
}

TEST_CASE("docs/file-formats.md lists every bridge curve source a scene can write, for each geometry", "[dem][bridge][docs]") {
    std::ifstream in(std::string(DEMSCALE_SOURCE_DIR) + "/docs/file-formats.md");
    REQUIRE(in);
    std::string line, page;
    while (std::getline(in, line)) page += line + "\n";
    for (const auto& [key, geometry] : {std::pair{"liquid.bridge_variant", bridge::BridgeGeometry::sphere_sphere},
                                        std::pair{"liquid.wall_bridge", bridge::BridgeGeometry::sphere_wall}}) {
        const auto row = page.find("| `" + std::string(key) + "` |");
        REQUIRE(row != std::string::npos);
        const auto cells = page.substr(row, page.find('\n', row) - row);
        for (const auto& source : bridge::curve_sources()) {
            INFO(key << ": " << source.value);
            CHECK((cells.find("`" + std::string(source.value) + "`") != std::string::npos) == source.has(geometry));
        }
    }
}

TEST_CASE("Every law a scene chooses declares its slot, choice, builder, deck words, report row and cache-key line",
          "[dem][parameters][engines]") {
    int chosen = 0;
    for (const auto& part : law_parts()) {
        if (part.choice.empty()) continue;  // a parameter group of the law before it
        ++chosen;
        INFO(part.name);
        REQUIRE(part.choose);
        // Choosing it makes it act, and its slot's other laws not.
        slump::SlumpScene s;
        part.choose(s);
        CHECK(part.active(s));
        for (const auto& other : law_parts())
            if (&other != &part && other.slot == part.slot && !other.choice.empty()) CHECK_FALSE(other.active(s));
        // Its words in the LIGGGHTS deck, or what the deck says instead.
        CHECK((!part.liggghts_model.empty() || !part.liggghts_note.empty()));
        // Its report row: the scene table names it among the contact laws.
        bool named = false;
        for (const auto& row : report::scene_table(s, "test").rows)
            if (std::get<std::string>(row[0]) == "contact laws")
                named = std::get<std::string>(row[1]).find(part.name) != std::string::npos;
        CHECK(named);
        // Its cache-key line: a scene that chooses another law of the slot has another key.
        for (const auto& other : law_parts())
            if (&other != &part && other.slot == part.slot && !other.choice.empty()) {
                slump::SlumpScene t;
                other.choose(t);
                CHECK(slump::scene_key(s) != slump::scene_key(t));
            }
    }
    CHECK(chosen == 5);
    // Its builder: every registered normal law is built from the settings (a compile error
    // otherwise), declares the normal slot, and pushes apart at an overlap.
    [&]<class... Law>(std::tuple<Law...>*) {
        ContactPair c;
        c.r_eff = 0.5e-3, c.sqrt_r_eff = std::sqrt(c.r_eff), c.overlap = 1e-6, c.contact_radius = std::sqrt(c.r_eff * c.overlap);
        auto check = [&]<class L>() {
            INFO(L::part->name);
            CHECK(L::part->slot == Slot::normal);
            CHECK(build_contact_law<ContactLaw<typename L::law, TangentialMindlin>>(ContactSettings{}, 1e-3).normal.elastic_force(c) > 0);
        };
        (check.template operator()<Law>(), ...);
    }(static_cast<normal_laws*>(nullptr));
}

TEST_CASE("A scene chooses the linear normal law: read, built, keyed, limited, refused and scaled", "[dem][parameters][engines]") {
    const auto path = write_scene("demscale_hooke.toml",
                                  "[contact]\nnormal_law = \"hooke\"\nlinear_stiffness_n_per_m = 300\nrestitution = 0.6\n[liquid]\nwet = false\n");
    const auto s = slump::load_slump_scene(path);
    CHECK(s.normal_law == "hooke");
    CHECK(hooke_part.active(s));
    CHECK_FALSE(hertz_part.active(s));
    // Built from the scene: F = k δ and F_d = 2β √(k m*) v_n with β = ln e / √(ln² e + π²), by hand.
    const auto law = build_contact_law<ContactLaw<NormalLinear, TangentialMindlin>>(s, s.radius_m);
    ContactPair c;
    c.overlap = 2e-6, c.m_eff = 4e-6, c.v_normal = -0.1;
    CHECK(law.normal.elastic_force(c) == Approx(300 * 2e-6).epsilon(1e-15));
    const double beta = std::log(0.6) / std::sqrt(std::log(0.6) * std::log(0.6) + std::numbers::pi * std::numbers::pi);
    CHECK(law.normal.damping_force(c) == Approx(2 * beta * std::sqrt(300 * 4e-6) * -0.1).epsilon(1e-14));
    // Its engine: the dry epsd line; none with the ledger, refused naming the list.
    CHECK(slump::listed_engine(s, false).normal == &hooke_part);
    CHECK_THROWS_AS(slump::listed_engine(s, true), InputError);
    // The step: the Rayleigh limit of E and ν, and t_c / 20 with t_c = π √(m*/k), m* = m/2.
    const double m = s.material.density * 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius_m, 3);
    const auto limits = time_step_limits(s, s.radius_m);
    REQUIRE(limits.size() == 2);
    CHECK(limits[0].seconds == Approx(rayleigh_time(s.material, s.radius_m)).epsilon(1e-15));
    CHECK(limits[1].seconds == Approx(std::numbers::pi * std::sqrt(m / 2 / 300)).epsilon(1e-14));
    CHECK(limits[1].fraction == 0.05);
    // The cache key: its own line, and k is an input only where the law acts.
    auto hertz = s;
    hertz.normal_law = "hertz";
    CHECK(slump::scene_key(s) != slump::scene_key(hertz));
    CHECK(slump::scene_text(s).find("\nlaw_hooke=1\n") != std::string::npos);
    CHECK(slump::scene_text(s).find("\ncontact.linear_stiffness_n_per_m=300\n") != std::string::npos);
    CHECK(slump::scene_text(hertz).find("linear_stiffness") == std::string::npos);
    // A value that names no law is refused with the list.
    CHECK_THROWS_WITH(slump::load_slump_scene(write_scene("demscale_hook.toml", "[contact]\nnormal_law = \"hook\"\n")),
                      Catch::Matchers::Contains("contact.normal_law = \"hook\": accepted one of \"hertz\", \"hooke\""));
    // Under S_f: k ∝ ρ L³ T⁻² takes S_f^k when named (S_f¹ at k = 1, where stresses are kept), else kept.
    for (double k : {1.0, 2.0}) {
        CHECK(slump::coarse_grained(s, {2, k, {"linear_stiffness"}}).material.linear_stiffness == Approx(300 * std::pow(2, k)).epsilon(1e-13));
        CHECK(slump::coarse_grained(s, {2, k, {}}).material.linear_stiffness == 300);
    }
}
