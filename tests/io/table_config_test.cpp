// Reading the Table 1 TOML: the shipped file, and every class of bad input with a message that
// names file, line, key, value and accepted range.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "core/input_error.hpp"
#include "io/table_config.hpp"

using namespace demscale;
using Catch::Matchers::Contains;

namespace {
std::string write_temp(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("demscale_test_" + name + ".toml");
    std::ofstream(path) << text;
    return path.string();
}
const std::string good = R"(
[particle]
radii_mm = [2.0, 1.0]
masses_g = [0.07, 0.01]
[liquid]
surface_tension_n_per_m = 0.074
)";
std::string error_of(const std::string& name, const std::string& text) {
    try {
        io::load_table_config(write_temp(name, text));
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}
}  // namespace

TEST_CASE("The shipped Table 1 file loads with the paper's values in SI", "[io][config]") {
    const auto c = io::load_table_config(DEMSCALE_SOURCE_DIR "/data/table1.toml");
    REQUIRE(c.radii_m.size() == 5);
    CHECK(c.radii_m[0] == Approx(3.84e-3));
    CHECK(c.tabulated_masses_kg[0] == Approx(0.52e-3));
    CHECK(c.liquid.surface_tension_n_per_m == 0.074);
    CHECK(c.liquid.moisture_content == 0.045);
    CHECK(c.liquid.contact_angle.radians() == 0.0);
    CHECK(c.bridge.variant == bridge::MikamiVariant::mikami1998);
    CHECK(c.exponents == std::vector<double>{1.0, 3.0});
    CHECK_FALSE(c.solid_density_kg_per_m3.has_value());
}

TEST_CASE("A minimal file gets documented defaults", "[io][config]") {
    const auto c = io::load_table_config(write_temp("minimal", good));
    CHECK(c.physical_radius_m == Approx(1e-3));
    CHECK(c.liquid.density_kg_per_m3 == 1000.0);
    CHECK(c.curve_points == 101);
}

TEST_CASE("Bad Table 1 inputs: one message naming the field, the value and the accepted range", "[io][config][errors]") {
    CHECK_THAT(error_of("negative", "[particle]\nradii_mm = [2.0, -1.0]\nmasses_g = [0.07, 0.01]\n"),
               Contains("particle.radii_mm[1] = -1") && Contains("> 0") && Contains(":2:"));
    CHECK_THAT(error_of("zero_radius", "[particle]\nradii_mm = [0]\nmasses_g = [0.01]\n"),
               Contains("particle.radii_mm[0] = 0"));
    CHECK_THAT(error_of("moisture", good + "moisture_content = 0.0\n"),
               Contains("liquid.moisture_content = 0") && Contains("(0, 1)"));
    CHECK_THAT(error_of("moisture_pct", good + "moisture_content = 4.5\n"), Contains("liquid.moisture_content = 4.5"));
    CHECK_THAT(error_of("theta", good + "contact_angle_deg = 90\n"),
               Contains("liquid.contact_angle_deg") && Contains("[0, 90) degrees"));
    CHECK_THAT(error_of("nan", good + "density_kg_per_m3 = nan\n"),
               Contains("liquid.density_kg_per_m3 = nan") && Contains("finite"));
    CHECK_THAT(error_of("typo", good + "surface_tension = 0.07\n"),
               Contains("unknown key") && Contains("did you mean liquid.surface_tension_n_per_m"));
    CHECK_THAT(error_of("section", good + "[liqid]\nx = 1\n"), Contains("did you mean [liquid]"));
    CHECK_THAT(error_of("type", good + "density_kg_per_m3 = \"water\"\n"), Contains("a number"));
    CHECK_THAT(error_of("variant", good + "[bridge]\nvariant = \"mikami\"\n"),
               Contains("bridge.variant") && Contains("mikami1998, yun-park-2017"));
    CHECK_THAT(error_of("malformed", "[particle\nradii_mm = [1.0]\n"), Contains("TOML"));
    CHECK_THAT(error_of("count", "[particle]\nradii_mm = [1.0, 2.0]\nmasses_g = [0.01]\n"), Contains("one per radius"));
    CHECK_THAT(error_of("points", good + "[curves]\npoints = 1.5\n"), Contains("integer in [2, 100000]"));
    CHECK_THROWS_WITH(io::load_table_config("/nonexistent/table.toml"), Contains("not found"));
}
