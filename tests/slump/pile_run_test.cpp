// A pile made elsewhere, measured as a slump run: the slump over the fill's height of two flat
// columns against their heights by hand, the S_f check on the spheres' radius, the mass warnings,
// and a runs file grown one run at a time, read back bit for bit and never left half-written.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.hpp"
#include "slump/coarse_grain.hpp"
#include "slump/pile_run.hpp"
#include "slump/runs_file.hpp"

using namespace demscale;
using namespace demscale::slump;
using Catch::Matchers::Contains;

namespace {

// A simple cubic column of `layers` layers of spheres of radius r touching each other, within a
// disc of radius `reach` around the axis: its surface stands at 2 r × layers.
dem::Particles column(double r, int layers, double reach) {
    dem::Particles p;
    const int n = static_cast<int>(reach / (2 * r));
    for (int k = 0; k < layers; ++k)
        for (int i = -n; i <= n; ++i)
            for (int j = -n; j <= n; ++j)
                if (std::hypot(2 * r * i, 2 * r * j) <= reach) p.add({2 * r * i, 2 * r * j, r + 2 * r * k}, r, 2500);
    return p;
}

std::string text_of(const std::filesystem::path& f) {
    std::ifstream in(f);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("A pile from elsewhere: slump over the fill's height of two flat columns, by hand", "[slump][pile]") {
    const SlumpScene scene;  // R = 1 mm, the reference cone
    const auto fill = column(1e-3, 20, 15e-3), pile = column(1e-3, 10, 15e-3);
    const auto run = measure_pile_run(pile, &fill, scene, 1, "--sf");
    // 40 mm and 20 mm columns: half the height lost. The Gibbs surface of a cubic lattice stands
    // within a few per cent of its top layer's top (docs/slump-measures.md).
    REQUIRE(run.fill_height);
    CHECK(*run.fill_height == Approx(40e-3).epsilon(0.03));
    CHECK(run.final.height == Approx(20e-3).epsilon(0.03));
    CHECK(*run.slump_over_height() == Approx(0.5).margin(0.02));
    // Half the spheres are gone, and the fill is not this scene's fill: both said.
    REQUIRE(run.warnings.size() == 2);
    CHECK_THAT(run.warnings[0], Contains("differs from the fill's by -50 %"));
    CHECK_THAT(run.warnings[1], Contains("not a same-mass fill of this scene"));
    const auto row = pile_run_row(run, 1, 0.074, 3, scene, "--fill");
    CHECK(row.slump_over_height == *run.slump_over_height());
    CHECK(row.slump_over_height == Approx(0.5).margin(0.02));  // by hand, as above
    CHECK(row.spread_over_d0 == run.final.spread / 0.038);
    CHECK(row.seed == 3);
    // Without a fill there is no slump to put in a runs row.
    const auto alone = measure_pile_run(pile, nullptr, scene, 1, "--sf");
    CHECK_FALSE(alone.slump_over_height());
    CHECK_THROWS_WITH(pile_run_row(alone, 1, 0.074, 3, scene, "--fill"), Contains("--fill = (not given)"));
}

TEST_CASE("A pile from elsewhere is measured at the S_f of its spheres", "[slump][pile]") {
    const SlumpScene fine;
    const auto coarse_pile = column(1.4e-3, 5, 15e-3);
    CHECK_THROWS_WITH(measure_pile_run(coarse_pile, nullptr, fine, 1, "--sf"),
                      Contains("--sf = 1: accepted the S_f of the file's spheres: their largest radius 1.4 mm is S_f 1.4 of the scene's 1 mm"));
    CHECK_NOTHROW(measure_pile_run(coarse_pile, nullptr, coarse_grained(fine, {1.4, 1, {}}), 1.4, "--sf"));
}

TEST_CASE("A runs file grows one run at a time and refuses a run it holds", "[slump][pile][runs]") {
    const auto dir = std::filesystem::temp_directory_path() / "demscale_append_run_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto file = (dir / "runs.csv").string();
    RunRow a;
    a.sf = 1.4, a.gamma = 0.074 * 1.4, a.seed = 2, a.slump_over_height = 0.1 + 0.2, a.spread_over_d0 = 1.0 / 3.0;
    RunRow b = a;
    b.seed = 3, b.slump_over_height = 0.2;
    append_run("--append-runs", file, a, "test");
    append_run("--append-runs", file, b, "test");
    const auto rows = read_runs_file(file, 0.074);
    REQUIRE(rows.size() == 2);
    CHECK(rows[0].slump_over_height == 0.1 + 0.2);  // bit for bit
    CHECK(rows[0].spread_over_d0 == 1.0 / 3.0);
    CHECK(rows[0].gamma == 0.074 * 1.4);
    CHECK(rows[1].seed == 3);
    const std::string before = text_of(file);
    CHECK_THROWS_WITH(append_run("--append-runs", file, a, "test"), Contains("seed 2: accepted a run the file does not hold yet"));
    CHECK(text_of(file) == before);
    const auto foreign = (dir / "other.csv").string();
    std::ofstream(foreign) << "sf,seed,slump_over_height,spread_over_d0,gamma_factor\n1,1,0.3,1.2,1\n";
    CHECK_THROWS_WITH(append_run("--append-runs", foreign, a, "test"), Contains("other.csv (header row) = other columns"));
    CHECK(text_of(foreign) == "sf,seed,slump_over_height,spread_over_d0,gamma_factor\n1,1,0.3,1.2,1\n");
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
    CHECK(files == 2);  // no temporary left behind
    std::filesystem::remove_all(dir);
}
