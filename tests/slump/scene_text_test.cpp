// A scene's text (what a Slurm task receives): read back, every input that decides a run is the
// original's, field by field; a text that was altered, written by another version, or malformed
// is refused with the line named.
#include <catch2/catch.hpp>
#include <string>

#include "core/input_error.hpp"
#include "core/version.hpp"
#include "slump/coarse_grain.hpp"
#include "slump/run_cache.hpp"
#include "slump/scene_text.hpp"

using namespace demscale;
using namespace demscale::slump;

namespace {

SlumpScene shipped(const std::string& name) { return load_slump_scene(DEMSCALE_SOURCE_DIR "/data/scenes/" + name); }

// Every input the run reads, compared with ==: a number that did not survive the text exactly fails.
void require_same_run(const SlumpScene& a, const SlumpScene& b) {
    CHECK(a.bottom_diameter_m == b.bottom_diameter_m);
    CHECK(a.top_diameter_m == b.top_diameter_m);
    CHECK(a.height_m == b.height_m);
    CHECK(a.lift_speed_m_per_s == b.lift_speed_m_per_s);
    CHECK(a.lift_height_m == b.lift_height_m);
    CHECK(a.radius_m == b.radius_m);
    CHECK(a.sizes.class_ratios == b.sizes.class_ratios);
    CHECK(a.sizes.mass_fractions == b.sizes.mass_fractions);
    CHECK(a.sizes.geometric_sd == b.sizes.geometric_sd);
    if (a.sizes.lognormal()) CHECK((a.sizes.lower_quantile == b.sizes.lower_quantile && a.sizes.upper_quantile == b.sizes.upper_quantile));
    CHECK(a.fill_height_m == b.fill_height_m);
    CHECK(a.seed == b.seed);
    CHECK(a.fill == b.fill);
    CHECK(a.rough_floor == b.rough_floor);
    if (a.rough_floor) CHECK(a.rough_floor_diameter_m == b.rough_floor_diameter_m);
    CHECK(a.dt_s == b.dt_s);
    CHECK(a.gravity == b.gravity);
    CHECK(a.settle_time_s == b.settle_time_s);
    CHECK(a.spread_time_s == b.spread_time_s);
    CHECK(a.pour_time_s == b.pour_time_s);
    CHECK(a.rest_speed_m_per_s == b.rest_speed_m_per_s);
    CHECK(a.rest_duration_s == b.rest_duration_s);
    CHECK(a.rest_quantile == b.rest_quantile);
    CHECK(a.skin_m == b.skin_m);
    CHECK(a.material.density == b.material.density);
    CHECK(a.rolling_resistance == b.rolling_resistance);
    CHECK(a.rolling_model == b.rolling_model);
    CHECK(a.wet == b.wet);
    CHECK(a.wet_walls == b.wet_walls);
    if (a.wet) {
        CHECK(a.bridge.variant == b.bridge.variant);
        CHECK(a.bridge.rupture == b.bridge.rupture);
        CHECK(a.particle_curve == b.particle_curve);
        if (a.wet_walls) CHECK(a.wall_curve == b.wall_curve);
        if (a.viscosity_pa_s > 0) CHECK(a.lubrication == b.lubrication);
    }
    for (const auto& part : dem::law_parts()) {
        REQUIRE(part.active(a) == part.active(b));
        if (part.active(a))
            for (const auto& p : part.parameters) {
                INFO(p.key);
                CHECK(p.get(a) == p.get(b));
            }
    }
}

}  // namespace

TEST_CASE("Scene text: every shipped scene and its variants read back as the same run", "[slump][scene_text]") {
    std::vector<SlumpScene> scenes;
    for (const char* name : {"kantro_wet.toml", "kantro_dry.toml", "kantro_dry_large.toml", "small_wet.toml", "repose_rough.toml",
                             "small_wet_lognormal.toml"}) {
        const auto s = shipped(name);
        scenes.push_back(s);
        scenes.push_back(coarse_grained(s, {2.74, 3, {}}));  // S_f and k give numbers like 0.0001*2.74^3
        scenes.push_back(coarse_grained(s, {1.4, 1.5, {"gravity", "youngs_modulus"}}));
    }
    auto exact = shipped("small_wet.toml");
    exact.particle_curve = bridge::CurveSource::exact, exact.wet_walls = true, exact.seed = 4000000001u;
    scenes.push_back(exact);
    auto fitted_walls = exact;
    fitted_walls.wall_curve = bridge::CurveSource::fit, fitted_walls.bridge.rupture = bridge::RuptureLaw::lian1993;
    fitted_walls.rolling_model = dem::RollingModel::epsd2, fitted_walls.radius_m = 1.0 / 3.0 * 1e-3;
    scenes.push_back(fitted_walls);
    auto willett = shipped("small_wet.toml");  // a curve source after format 5: its own line
    willett.particle_curve = bridge::CurveSource::willett;
    scenes.push_back(willett);
    CHECK(scene_key(willett) != scene_key(shipped("small_wet.toml")));
    CHECK(scene_key(willett) != scene_key(exact));
    // A fitted scene writes no curve line: its key stays what it was before the sources were listed.
    CHECK(scene_text(shipped("kantro_wet.toml")).find("curve_") == std::string::npos);
    auto unbounded = shipped("kantro_wet.toml");  // viscous: the lubrication's form is part of the run
    unbounded.lubrication = dem::Lubrication::unbounded;
    scenes.push_back(unbounded);
    CHECK(scene_key(unbounded) != scene_key(shipped("kantro_wet.toml")));
    auto sieve = shipped("small_wet.toml");  // a sieve table: a line per class, and its own key
    sieve.sizes.class_ratios = {0.6, 1.0, 1.3, 1.31}, sieve.sizes.mass_fractions = {0.1, 0.4, 0.3, 0.2};
    scenes.push_back(sieve);
    CHECK(scene_key(sieve) != scene_key(shipped("small_wet.toml")));
    CHECK(scene_key(shipped("small_wet_lognormal.toml")) != scene_key(shipped("small_wet.toml")));
    // One radius writes no size line: its key stays what it was before distributions.
    CHECK(scene_text(shipped("small_wet.toml")).find("size") == std::string::npos);
    for (const auto& s : scenes) {
        INFO(s.name << " R = " << s.radius_m);
        const auto back = scene_from_text(scene_text(s), "task.scene");
        require_same_run(s, back);
        CHECK(scene_key(back) == scene_key(s));
    }
}

TEST_CASE("Scene text: an altered, foreign or malformed text is refused, naming the line", "[slump][scene_text]") {
    const std::string text = scene_text(shipped("small_wet.toml"));
    auto refused = [](const std::string& t, const std::string& message) {
        try {
            scene_from_text(t, "x.scene");
            FAIL("accepted: " << t);
        } catch (const InputError& e) {
            INFO(e.what());
            CHECK(std::string(e.what()).find(message) != std::string::npos);
        }
    };
    // A line the reader does not know, a line out of order, a dropped line.
    refused(text + "colour=3\n", "colour");
    const auto seed = text.find("seed=");
    const auto seed_end = text.find('\n', seed) + 1;
    std::string moved = text;
    const std::string seed_line = moved.substr(seed, seed_end - seed);
    moved.erase(seed, seed_end - seed);
    refused(moved + seed_line, "reads back as another scene");
    refused(moved, "reads back as another scene");
    // Another build or cache format.
    std::string other = text;
    other.replace(other.find(version), std::string(version).size(), "0.0.0-other");
    refused(other, "x.scene:1");
    std::string format = text;
    const auto cache_at = format.find("cache=");
    format.replace(cache_at, format.find('\n', cache_at) - cache_at, "cache=1");
    refused(format, "x.scene:2");
    // A value that is not a number.
    std::string bad = text;
    bad.insert(seed_end - 1, "x");
    refused(bad, "NAME=NUMBER");
    // A changed value is read as such: another seed, another key.
    std::string reseeded = text;
    reseeded.replace(seed, seed_end - seed, "seed=7\n");
    const auto back = scene_from_text(reseeded, "x.scene");
    CHECK(back.seed == 7u);
    CHECK(scene_key(back) != scene_key(shipped("small_wet.toml")));
}

TEST_CASE("Scene text: the benchmarks' larger scene is kantro_dry in a cone 1.5 times as large", "[slump][scene_text]") {
    // bench/vs_liggghts.sh's larger scene must differ from the reference dry scene only in size,
    // or its ratios would not describe the same run grown: the cone and the fill height 1.5x,
    // the lift 8.5 mm past the cone's top (1.5 x 57 + 8.5 = 94 mm), everything else equal.
    const SlumpScene small = shipped("kantro_dry.toml");
    SlumpScene large = shipped("kantro_dry_large.toml");
    CHECK(large.bottom_diameter_m == Approx(1.5 * small.bottom_diameter_m).epsilon(1e-12));
    CHECK(large.top_diameter_m == Approx(1.5 * small.top_diameter_m).epsilon(1e-12));
    CHECK(large.height_m == Approx(1.5 * small.height_m).epsilon(1e-12));
    CHECK(large.fill_height_m == Approx(1.5 * small.fill_height_m).epsilon(1e-12));
    CHECK(large.lift_height_m == Approx(0.094).epsilon(1e-12));
    large.bottom_diameter_m = small.bottom_diameter_m, large.top_diameter_m = small.top_diameter_m;
    large.height_m = small.height_m, large.fill_height_m = small.fill_height_m, large.lift_height_m = small.lift_height_m;
    require_same_run(large, small);
}
