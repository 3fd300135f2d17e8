// Runs made by LIGGGHTS: what a scene must be for LIGGGHTS to run it (refused before any run
// otherwise), the run cache keeping them apart from demscale's own, and the deck's step counts by hand.
// The trip itself (mpirun, dump, measures, verdict) is tests/cli/liggghts_test.sh.
#include <catch2/catch.hpp>

#include "core/input_error.hpp"
#include "slump/liggghts_export.hpp"
#include "slump/liggghts_run.hpp"
#include "slump/run_cache.hpp"
#include "slump/scene_text.hpp"

using namespace demscale;
using namespace demscale::slump;
using Catch::Matchers::Contains;

TEST_CASE("A scene LIGGGHTS cannot express is refused before any run, naming its keys", "[slump][liggghts]") {
    SlumpScene s;  // wet, dry walls, Mikami's fit
    s.source = "scene.toml";
    SlumpScene walls = s;
    walls.wet_walls = true;
    CHECK_THROWS_WITH(use_liggghts(walls, 2, "--ranks"), Contains("scene.toml: liquid.wet_walls = true: accepted false with --engine liggghts"));
    SlumpScene exact = s;
    exact.particle_curve = bridge::CurveSource::exact;
    CHECK_THROWS_WITH(use_liggghts(exact, 2, "--ranks"), Contains("scene.toml: liquid.bridge_variant = table"));
    CHECK_THROWS_WITH(use_liggghts(s, 0, "--ranks"), Contains("--ranks = 0: accepted 1 to 64"));
    CHECK_THROWS_WITH(use_liggghts(s, 65, "--ranks"), Contains("--ranks = 65"));
    CHECK(walls.liggghts_ranks == 0);
    // A dry scene with wet walls has no bridge at all: nothing to refuse.
    SlumpScene dry = walls;
    dry.wet = false;
    CHECK_NOTHROW(use_liggghts(dry, 1, "--ranks"));
    CHECK(dry.liggghts_ranks == 1);
}

TEST_CASE("LIGGGHTS' runs have keys of their own, and their scene text travels", "[slump][liggghts]") {
    SlumpScene s;
    const std::string own = scene_text(s);
    CHECK(own.find("liggghts_ranks") == std::string::npos);  // demscale's runs keep their keys
    use_liggghts(s, 2, "--ranks");
    const std::string theirs = scene_text(s);
    CHECK(theirs.find("\nliggghts_ranks=2\n") != std::string::npos);
    CHECK(scene_key(s) != scene_key(SlumpScene{}));
    CHECK(scene_from_text(theirs, "t").liggghts_ranks == 2);  // a Slurm task runs it on LIGGGHTS too
}

TEST_CASE("The deck's step counts, by hand", "[slump][liggghts]") {
    SlumpScene s;
    s.dt_s = 2e-5, s.lift_height_m = 0.065, s.lift_speed_m_per_s = 0.3, s.spread_time_s = 0.2;
    const auto steps = deck_steps(s);
    CHECK(steps.lift == 10833);  // 65 mm / 0.3 m/s / 2e-5 s = 10 833.3
    CHECK(steps.spread == 10000);
    s.rest_duration_s = 0.01;
    CHECK(deck_steps(s).rest_check == 125);  // a quarter of 0.01 s at 2e-5 s: five checks span the rest duration
    s.rest_duration_s = 1e30;                 // slump --fixed-time: one check per spread, never five
    CHECK(deck_steps(s).rest_check == 10000);
}
