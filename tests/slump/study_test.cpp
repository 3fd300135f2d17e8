// Coarse-graining study pieces: the scaled scene (against hand algebra), the similarity groups of an
// exponent (hand derivation), comparison with a fine ensemble on constructed profiles and piles, the
// run cache, and replacement
// conserving mass and liquid.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "bridge/liquid_volume.hpp"
#include "core/input_error.hpp"
#include "similarity/exponent_similarity.hpp"
#include "slump/coarse_grain.hpp"
#include "slump/comparison.hpp"
#include "slump/ensemble_verdict.hpp"
#include "slump/fill.hpp"
#include "slump/response_study.hpp"
#include "slump/run_cache.hpp"
#include "slump/runs_verdict.hpp"
#include "slump/second_look.hpp"
#include "report/slump_study_tables.hpp"
#include "slump/study.hpp"

using namespace demscale;
using namespace demscale::slump;

namespace {
SlumpScene kantro() { return load_slump_scene(DEMSCALE_SOURCE_DIR "/data/scenes/kantro_wet.toml"); }

// A result whose profile is h(r) = max(0, H - r) sampled on bins of width w (centres (i + ½) w).
SlumpResult triangle(double H, double w, double slump, double d95) {
    SlumpResult r;
    for (double c = 0.5 * w; c < H + w; c += w) r.final.profile.push_back({c, std::max(0.0, H - c)});
    r.initial_height = 0.05;
    r.final.height = 0.05 - slump;
    r.final.spread = d95;
    r.final.spread_max = d95;
    return r;
}
std::vector<const SlumpResult*> ptrs(const std::vector<SlumpResult>& v) {
    std::vector<const SlumpResult*> p;
    for (const auto& r : v) p.push_back(&r);
    return p;
}
}  // namespace

TEST_CASE("Coarse scene: R, gamma, skin and dt scale as the algebra says, the rest is held", "[slump][coarse]") {
    const auto fine = kantro();
    const double sf = 2.74;
    for (double k : {1.0, 3.0}) {
        const auto c = coarse_grained(fine, {sf, k, {}});
        CHECK(c.radius_m == Approx(sf * fine.radius_m).epsilon(1e-14));
        CHECK(c.liquid.surface_tension_n_per_m == Approx(fine.liquid.surface_tension_n_per_m * std::pow(sf, k)).epsilon(1e-14));
        // Rayleigh time ∝ R √(ρ/G): at fixed material the step grows by S_f.
        CHECK(c.dt_s == Approx(sf * fine.dt_s).epsilon(1e-12));
        CHECK(c.gravity == fine.gravity);
        CHECK(c.material.youngs_modulus == fine.material.youngs_modulus);
        CHECK(c.lift_speed_m_per_s == fine.lift_speed_m_per_s);
        CHECK(c.top_diameter_m == fine.top_diameter_m);
    }
    // k = 3 implies S_T = 1 (t = (3 - k)/2 = 0), so the basis demands g × S_f, E × S_f², v × S_f.
    const auto c = coarse_grained(fine, {sf, 3.0, {"gravity", "youngs_modulus", "velocity"}});
    CHECK(c.gravity == Approx(fine.gravity * sf).epsilon(1e-12));
    CHECK(c.material.youngs_modulus == Approx(fine.material.youngs_modulus * sf * sf).epsilon(1e-12));
    CHECK(c.lift_speed_m_per_s == Approx(fine.lift_speed_m_per_s * sf).epsilon(1e-12));
    // Rayleigh time ∝ R/√E: S_f / √(S_f²) = 1, the step the basis demands (S_T = 1).
    CHECK(c.dt_s == Approx(fine.dt_s).epsilon(1e-12));
    // μ ~ ρ L² T⁻¹: S_f² / S_f^t; k = 3 (t = 0) demands μ × S_f², k = 1 (t = 1) μ × S_f.
    auto wet = fine;
    wet.viscosity_pa_s = 1e-3;
    CHECK(coarse_grained(wet, {sf, 3.0, {"viscosity"}}).viscosity_pa_s == Approx(1e-3 * sf * sf).epsilon(1e-12));
    CHECK(coarse_grained(wet, {sf, 1.0, {"viscosity"}}).viscosity_pa_s == Approx(1e-3 * sf).epsilon(1e-12));
    CHECK(coarse_grained(wet, {sf, 1.0, {}}).viscosity_pa_s == 1e-3);  // held unless named
    CHECK_THROWS_WITH(coarse_grained(fine, {sf, 1.0, {"stiffness"}}), Catch::Matchers::Contains("--scale = stiffness"));
    CHECK_THROWS_WITH(coarse_grained(fine, {10.0, 1.0, {}}), Catch::Matchers::Contains("--sf = 10") &&
                                                                Catch::Matchers::Contains("top opening"));
    CHECK_THROWS_AS(coarse_grained(fine, {-1.0, 1.0, {}}), InputError);
}

TEST_CASE("Geometry warnings: opening, height and count thresholds", "[slump][coarse]") {
    const auto fine = kantro();
    CHECK(geometry_warnings(fine, 4900).empty());  // 19 mm / 2 mm = 9.5 diameters, 27 high
    const auto w = geometry_warnings(coarse_grained(fine, {2.74, 1.0, {}}), 150);
    REQUIRE(w.size() == 3);  // 19 / 5.48 = 3.5 across, 54 / 5.48 = 9.9 high, 150 particles
    CHECK_THAT(w[0], Catch::Matchers::Contains("3.5 diameters wide"));
    CHECK_THAT(w[1], Catch::Matchers::Contains("9.9 diameters high"));
}

TEST_CASE("Geometry limits: Table 1's S_f in the reference cone, by hand, and a study runs only the usable ones",
          "[slump][coarse]") {
    const auto fine = kantro();
    // Fill: 0.5 of the frustum below 54 mm (radii 19 and 10 mm), 18 407 mm³ of solid. At S_f 2.74:
    // 19 / 5.48 = 3.5 diameters across (< 4), 54 / 5.48 = 9.9 high, 214 spheres; at 3.84: 2.5 across,
    // 7.0 high (< 8), 78 spheres (< 200); 1.4 and 1.96 (6.8 and 4.8 across, 1 601 and 584 spheres) pass.
    CHECK(usable_scale_factors(fine, table1_scale_factors) == std::vector<double>{1.4, 1.96});
    const auto at_274 = geometry_limits(fine, 2.74);
    REQUIRE(at_274.size() == 1);
    CHECK_THAT(at_274[0], Catch::Matchers::Contains("3.5 diameters wide (< 4)"));
    const auto at_384 = geometry_limits(fine, 3.84);
    REQUIRE(at_384.size() == 3);
    CHECK_THAT(at_384[1], Catch::Matchers::Contains("7 diameters high (< 8)"));
    CHECK_THAT(at_384[2], Catch::Matchers::Contains("78 particles (< 200)"));
    CHECK_THAT(geometry_limits(fine, 10).at(0), Catch::Matchers::Contains("do not pass the top opening"));
    auto lowered = fine;  // a scene's own limits decide
    lowered.limits.opening_diameters = 3;
    CHECK(geometry_limits(lowered, 2.74).empty());

    StudyPlan plan;
    plan.fine = fine, plan.scale_factors = {1.4, 2.74}, plan.exponents = {1, 3}, plan.seeds = 2;
    const auto study = plan_study(plan);
    REQUIRE(study.limited.size() == 1);
    CHECK(study.limited[0].sf == 2.74);
    REQUIRE(study.runs.size() == 2);  // k = 1 and 3 at S_f 1.4 only
    CHECK(study.runs[0].grain.sf == 1.4);
    CHECK(study.runs[1].grain.sf == 1.4);
    CHECK(study.coarse_seeds.size() == 2);
    CHECK(study.overall() == stats::Verdict::inconclusive);  // nothing judged yet: neither PASS nor FAIL
    // The dry control: the fine scene and each coarse one without liquid, every seed; the dry coarse
    // scenes of k = 1 and 3 are one scene (k scales only gamma), so they run once.
    REQUIRE(study.dry_fine.size() == 2);
    REQUIRE(study.dry_coarse.size() == 2);
    CHECK(!study.dry_fine[0].scene.wet);
    CHECK(study.dry_fine[1].scene.seed == fine.seed + 1);
    CHECK(study.dry_coarse[1][1].scene.radius_m == Approx(1.4 * fine.radius_m));
    CHECK(scene_key(study.dry_coarse[0][0].scene) == scene_key(study.dry_coarse[1][0].scene));
    CHECK(scene_key(study.dry_fine[0].scene) != scene_key(study.reference.scene));
    plan.baseline = Baseline::none;
    CHECK(!plan_study(plan).has_control());
}

TEST_CASE("Similarity groups of an exponent: hand-derived S_f powers", "[similarity][exponent]") {
    // γ ~ ρ L³ T⁻²; S_ρ = 1, S_L = S_f: S_f^k = S_f^(3 - 2t), t = (3 - k)/2. F = γ R f: S_f^(k+1).
    // Bond F/(ρ g R³), g held: k + 1 - 3. Stress F/R²: k + 1 - 2. Particle Froude v²/(g R): -1.
    for (double k : {1.0, 1.5, 2.0, 3.0}) {
        const auto s = similarity::exponent_similarity(k);
        INFO("k = " << k);
        CHECK(s.time_exponent == Approx((3 - k) / 2).margin(1e-14));
        CHECK(s.groups[0].sf_exponent == Approx(k - 1).margin(1e-14));
        CHECK(s.groups[1].sf_exponent == Approx(k - 2).margin(1e-14));
        CHECK(s.groups[5].sf_exponent == Approx(-1).margin(1e-14));
        // Held g, E, v, μ; the basis demands L/T² → 1 - 2t, ρL²/T² → 2 - 2t, L/T → 1 - t, ρL²/T → 2 - t.
        const double t = (3 - k) / 2;
        CHECK(s.held[0].demanded_exponent == Approx(1 - 2 * t).margin(1e-14));
        CHECK(s.held[1].demanded_exponent == Approx(2 - 2 * t).margin(1e-14));
        CHECK(s.held[2].demanded_exponent == Approx(1 - t).margin(1e-14));
        CHECK(s.held[3].demanded_exponent == Approx(2 - t).margin(1e-14));  // μ: ρ L² / T
    }
    CHECK(similarity::exponent_similarity(1).groups[0].kept());   // k = 1 keeps the stress (Eq. 11)
    CHECK(similarity::exponent_similarity(2).groups[1].kept());   // k = 2 keeps the Bond number
    CHECK_FALSE(similarity::exponent_similarity(3).groups[1].kept());
}

TEST_CASE("Run comparison against the fine ensemble on constructed profiles: known differences and speed-ups", "[slump][compare]") {
    const double w = 0.002;
    const auto fine = triangle(0.02, w, 0.02, 0.1);
    const auto ref = fine_reference({&fine}, 0.5 * w);
    SECTION("the same pile sampled on coarser bins is almost the same shape") {
        // Linear interpolation of a linear flank is exact; only the apex bin and the foot differ.
        const auto coarse = triangle(0.02, 2 * w, 0.02, 0.1);
        const auto c = compare_to(ref, coarse);
        CHECK(c.slump_error == 0);
        CHECK(c.spread_error == 0);
        CHECK(c.profile_error < 0.05);
    }
    SECTION("a pile lower by a constant factor has that factor as its distance; slump in fill heights") {
        auto lower = fine;
        for (auto& p : lower.final.profile) p.height *= 0.8;
        lower.final.height = 0.05 - 0.025;
        lower.final.spread = 0.11;
        const auto c = compare_to(ref, lower);
        CHECK(c.profile_error == Approx(0.2).epsilon(1e-12));
        CHECK(c.slump_error == Approx(0.1).epsilon(1e-12));  // 25/50 against 20/50 of the fill height
        CHECK(c.spread_error == Approx(0.1).epsilon(1e-12));
    }
    SECTION("the fine reference averages its runs") {
        auto taller = fine;
        for (auto& p : taller.final.profile) p.height *= 1.2;
        taller.final.height = 0.05 - 0.015;
        const auto two = fine_reference({&fine, &taller}, 0.5 * w);
        CHECK(two.slump_over_height == Approx(0.5 * (0.4 + 0.3)));
        CHECK(compare_to(two, fine).profile_error == Approx(0.1 / 1.1).epsilon(1e-9));  // |1 − 1.1| / 1.1
    }
    SECTION("speed-ups: wall time ratio and particle-step ratio") {
        auto f = fine, c = fine;
        f.particles = 4900, f.steps = 100000, f.wall_s = 200;
        c.particles = 650, c.steps = 50000, c.wall_s = 10;
        const auto x = compare_to(fine_reference({&f}, 0.5 * w), c);
        CHECK(x.wall_speedup == Approx(20));
        CHECK(x.work_speedup == Approx(4900.0 * 100000 / (650.0 * 50000)));
    }
    CHECK(profile_height_at(fine.final.profile, 0.0) == Approx(0.019));
    CHECK(profile_height_at(fine.final.profile, 0.004) == Approx(0.016));
    CHECK(profile_height_at(fine.final.profile, 1.0) == 0);
}

TEST_CASE("Profile distance of two constructed piles of one shape at different S_f is near zero, the raw rule is not",
          "[slump][compare]") {
    // A conical heap, tops on h(ρ) = H − ρ tan α, built of spheres of radius R and of 2R, each with a
    // sparse fringe of lone spheres on the floor every 5 mm beyond the foot (as spheres rolled away).
    const double H = 0.03, t = std::tan(30 * M_PI / 180), base = H / t;
    auto pile = [&](double r) {
        dem::Particles p;
        for (double rho = 0; rho <= base; rho += 0.5 * r) {
            const int n = std::max(1, static_cast<int>(2 * M_PI * rho / (2 * r)));
            for (int k = 0; k < n; ++k) {
                const double phi = 2 * M_PI * k / n, top = std::max(H - rho * t, 2 * r);
                p.add({rho * std::cos(phi), rho * std::sin(phi), top - r}, r, 2500);
            }
        }
        for (double rho = base + 0.005; rho < base + 0.03; rho += 0.005) p.add({rho, 0, r}, r, 2500);
        // The rules act on whatever profile a pile carries; they were made for the sphere-top profile
        // (highest top per 2R bin), where a fringe and empty bins arise, so the test feeds that one.
        auto m = measure_pile(p, 2 * r, {1e-3, 5e-3});
        m.profile = m.profile_tops;
        return m;
    };
    SlumpResult fine, coarse;
    fine.final = pile(1e-3), coarse.final = pile(2e-3);
    fine.initial_height = coarse.initial_height = 0.05;
    const auto ref = fine_reference({&fine}, 1e-3, coarse.final.spread_max);
    const double shaped = compare_to(ref, coarse).profile_error;
    // The same comparison on raw heights (fringe counted, empty bins as zero), the old rule.
    double d2 = 0, r2 = 0;
    for (double x : ref.radii) {
        const double hf = profile_height_at(fine.final.profile, x), hc = profile_height_at(coarse.final.profile, x);
        d2 += (hc - hf) * (hc - hf), r2 += hf * hf;
    }
    const double raw = std::sqrt(d2 / r2);
    INFO("shape rule " << shaped << ", raw rule " << raw);
    CHECK(shaped < 0.05);
    CHECK(raw > 2 * shaped);
    // And a different shape is told apart: a heap half as high at the same base.
    SlumpResult flat = fine;
    for (auto& q : flat.final.profile) q.height = q.height > 2.5e-3 ? 0.5 * q.height : q.height;
    CHECK(compare_to(ref, flat).profile_error > 0.3);
}

TEST_CASE("Run cache: keyed by every scene parameter, round trip, unreadable entries ignored", "[slump][cache]") {
    const auto s = kantro();
    auto t = s;
    CHECK(scene_key(s) == scene_key(t));
    t.name = "renamed", t.source = "elsewhere.toml";
    CHECK(scene_key(s) == scene_key(t));  // the label does not change the physics
    t.material.rolling_friction *= 1 + 1e-15;
    CHECK(scene_key(s) != scene_key(t));
    t = s, t.seed = 2;
    CHECK(scene_key(s) != scene_key(t));

    const auto dir = std::filesystem::temp_directory_path() / "demscale_cache_test";
    std::filesystem::remove_all(dir);
    const RunCache cache(dir);
    CHECK_FALSE(cache.load("0123456789abcdef"));
    SlumpResult r = triangle(0.02, 0.002, 0.01, 0.08);
    r.final.foot = 0.002;
    r.particles = 2, r.steps = 10, r.wall_s = 1.5, r.came_to_rest = true, r.final.repose_angle_deg = 30;
    r.history = {{0.0, 0.05, 0.04, {}}, {0.005, 0.049, 0.041, {}}};
    r.history[1].energy.kinetic = 2e-4, r.history[1].energy.dissipated.bridge = 3e-5, r.history[1].energy.wall_work = 1e-6;
    r.final_state.add({0, 0, 0.001}, 0.001, 2200);
    r.final_state.add({0.002, 0, 0.001}, 0.001, 2200);
    cache.store("0123456789abcdef", r, 1);
    const auto back = cache.load("0123456789abcdef");
    REQUIRE(back);
    CHECK(back->slump() == r.slump());
    CHECK(back->final.foot == r.final.foot);
    CHECK(back->final.profile.size() == r.final.profile.size());
    CHECK(back->final.profile[3].height == r.final.profile[3].height);
    REQUIRE(back->history.size() == 2);
    CHECK(back->history[1].energy.kinetic == 2e-4);  // the ledger travels field by field
    CHECK(back->history[1].energy.dissipated.bridge == 3e-5);
    CHECK(back->history[1].energy.wall_work == 1e-6);
    CHECK(back->final_state.size() == 2);
    CHECK(back->came_to_rest);
    std::ofstream(dir / "0123456789abcdef.json") << "{ truncated";
    CHECK_FALSE(cache.load("0123456789abcdef"));
    // A fill the cone could not hold is remembered by its reason, not poured again.
    CHECK_FALSE(cache.load_unusable("fedcba9876543210"));
    cache.store_unusable("fedcba9876543210", "fill: the cone holds 37.4 g");
    CHECK(cache.load_unusable("fedcba9876543210") == std::optional<std::string>("fill: the cone holds 37.4 g"));
    CHECK_FALSE(cache.load("fedcba9876543210"));
}

TEST_CASE("Replacement conserves mass and liquid: coarse fills of the cone against the fine one", "[slump][coarse][fill]") {
    // Same cone, same fill mass: every fill is cut to ρ φ_fill V(fill height), so a coarse fill weighs
    // what the fine one does to half a coarse sphere (a cut by the sphere tops lost a boundary layer
    // about one radius thick, 7 % at S_f 1.4 and 16 % at 1.96 on the lattice).
    const auto fine = kantro();
    const auto fill_f = fill_cone(fine);
    auto mass = [](const dem::Particles& p) {
        double m = 0;
        for (double x : p.mass) m += x;
        return m;
    };
    for (double sf : {1.4, 1.96}) {
        const auto coarse = coarse_grained(fine, {sf, 1.0, {}});
        const auto fill_c = fill_cone(coarse);
        const double ratio = mass(fill_c) / mass(fill_f);
        INFO("S_f = " << sf << ", mass ratio " << ratio << ", particles " << fill_c.size() << " vs " << fill_f.size());
        CHECK(std::abs(mass(fill_c) - fill_mass(fine)) <= 0.5 * fill_c.mass[0]);
        CHECK(std::abs(ratio - 1.0) <= fill_c.mass[0] / mass(fill_f));
        // Liquid per bridge (Eq. 5) follows the mass: V̄ = S_f³ V, so V̂ = V/R³ is unchanged and the
        // total liquid φ·m/ρ_l follows the same ratio as the mass.
        const double v_f = bridge::liquid_bridge_volume(fine.liquid.moisture_content, fill_f.mass[0], fine.liquid.density_kg_per_m3);
        const double v_c = bridge::liquid_bridge_volume(coarse.liquid.moisture_content, fill_c.mass[0], coarse.liquid.density_kg_per_m3);
        CHECK(v_c / v_f == Approx(sf * sf * sf).epsilon(1e-12));
    }
}

TEST_CASE("Ensemble verdict on constructed runs: PASS, FAIL, INCONCLUSIVE where they must be, with reasons", "[slump][verdict]") {
    // Runs whose slump over the 50 mm fill height is m + s z_i (z a fixed pattern, mean 0, sd 1) and
    // whose profile is the matching triangle: known means and spreads.
    const std::vector<double> z = {-1.5, -1.0, -0.5, 0.0, 0.0, 0.5, 1.0, 1.5};
    const double zs = 1 / std::sqrt((2 * 2.25 + 2 * 1.0 + 2 * 0.25) / 7);
    auto ensemble = [&](double mean_slump, double sd, double d95) {
        std::vector<SlumpResult> v;
        for (double x : z) {
            const double slump = mean_slump + sd * zs * x;
            auto r = triangle(0.05 - slump, 0.002, slump, d95 * (1 + 0.002 * x));
            r.final.foot = 0.002;
            v.push_back(r);
        }
        return v;
    };
    Tolerances tol;
    tol.slump = 0.05, tol.spread = 0.05, tol.profile = 0.15;
    const auto fine = ensemble(0.020, 0.001, 0.10);
    SECTION("the same distribution passes every criterion") {
        const auto v = judge_ensemble(ptrs(fine), ptrs(ensemble(0.020, 0.001, 0.10)), 1.4, 1, tol, 1e-3, true);
        REQUIRE(v.criteria.size() == 3);
        for (const auto& c : v.criteria) CHECK(c.verdict == stats::Verdict::pass);
        CHECK(v.overall == stats::Verdict::pass);
        CHECK(v.warnings.empty());
    }
    SECTION("a column that does not slump fails on slump (0.4 of the height apart)") {
        const auto v = judge_ensemble(ptrs(fine), ptrs(ensemble(0.0, 0.0, 0.10)), 1.4, 3, tol, 1e-3, true);
        CHECK(v.criteria[0].verdict == stats::Verdict::fail);
        CHECK(v.criteria[0].estimate == Approx(-0.4).epsilon(1e-9));
        CHECK(v.overall == stats::Verdict::fail);
    }
    SECTION("noisy coarse runs straddle the tolerance: INCONCLUSIVE, with the smallest confirmable tolerance") {
        const auto v = judge_ensemble(ptrs(fine), ptrs(ensemble(0.021, 0.004, 0.10)), 1.4, 1, tol, 1e-3, true);
        CHECK(v.criteria[0].verdict == stats::Verdict::inconclusive);
        CHECK(v.criteria[0].smallest_tolerance > tol.slump);
        CHECK(v.overall == stats::Verdict::inconclusive);
    }
    SECTION("a reference slumping less than a coarse diameter cannot discriminate: INCONCLUSIVE with the reason") {
        const auto still = ensemble(0.001, 0.0001, 0.10);
        const auto v = judge_ensemble(ptrs(still), ptrs(still), 1.96, 1, tol, 1e-3, true);
        CHECK(v.criteria[0].verdict == stats::Verdict::inconclusive);
        CHECK(v.criteria[0].reason.find("cannot tell exponents apart") != std::string::npos);
    }
    SECTION("one seed is an anecdote: INCONCLUSIVE; a tolerance under the noise warns; a dry scene says k has no effect") {
        const auto one = judge_ensemble(ptrs(fine), {&fine[3]}, 1.4, 1, tol, 1e-3, true);
        CHECK(one.overall == stats::Verdict::inconclusive);
        CHECK(one.criteria[1].reason.find("fewer than two seeds") != std::string::npos);
        Tolerances tight = tol;
        tight.slump = 1e-4;
        const auto dry = judge_ensemble(ptrs(fine), ptrs(fine), 1.4, 1, tight, 1e-3, false);
        REQUIRE(dry.warnings.size() == 2);
        CHECK(dry.warnings[0].find("below the fine ensemble's own spread") != std::string::npos);
        CHECK(dry.warnings[1].find("no effect") != std::string::npos);
    }
}

TEST_CASE("Ensemble verdict against a dry control: the geometry's offset fails raw and is removed seed by seed",
          "[slump][verdict][baseline]") {
    // Piles given by their heights on bins of 2 mm; each seed's slump is m + s z_i. The coarse piles
    // stand 1 mm higher near the axis and slump 0.006 m more, spread 6 % further, wet and dry alike:
    // the offset a coarse S_f shows without liquid. Raw it fails; corrected it passes.
    const std::vector<double> z = {-1.5, -1.0, -0.5, 0.0, 0.0, 0.5, 1.0, 1.5};
    auto pile = [](double top, double slope, double bump, double slump, double spread) {
        SlumpResult r;
        for (double c = 0.001; c < 0.06; c += 0.002)
            r.final.profile.push_back({c, std::max(0.0, top - slope * c) + (c < 0.01 ? bump : 0.0)});
        r.initial_height = 0.05, r.final.height = 0.05 - slump, r.final.spread = spread, r.final.spread_max = spread;
        r.final.foot = 0.0005;
        return r;
    };
    auto ensemble = [&](double top, double slope, double bump, double slump, double spread) {
        std::vector<SlumpResult> v;
        for (double x : z) v.push_back(pile(top, slope, bump, slump + 0.0005 * x, spread * (1 + 0.002 * x)));
        return v;
    };
    Tolerances tol;
    tol.slump = 0.05, tol.spread = 0.05, tol.profile = 0.02;
    const auto fine = ensemble(0.03, 1.0, 0, 0.020, 0.10), coarse = ensemble(0.03, 1.0, 0.001, 0.026, 0.106);
    const auto dry_fine = ensemble(0.02, 0.5, 0, 0.030, 0.12), dry_coarse = ensemble(0.02, 0.5, 0.001, 0.036, 0.126);
    const auto raw = judge_ensemble(ptrs(fine), ptrs(coarse), 1.4, 1, tol, 1e-3, true);
    CHECK(raw.criteria[0].estimate == Approx(0.12));  // 6 mm of 50
    CHECK(raw.criteria[0].verdict == stats::Verdict::fail);
    CHECK(raw.criteria[1].estimate == Approx(0.06));
    CHECK(raw.criteria[1].verdict == stats::Verdict::fail);
    CHECK(raw.criteria[2].estimate > 0.03);  // the 1 mm bump over the first five bins
    CHECK(raw.criteria[2].verdict == stats::Verdict::fail);
    const DryControl control{ptrs(dry_fine), ptrs(dry_coarse)};
    const auto corrected = judge_ensemble(ptrs(fine), ptrs(coarse), 1.4, 1, tol, 1e-3, true, &control);
    CHECK(corrected.criteria[0].estimate == Approx(0.0).margin(1e-12));
    CHECK(corrected.criteria[1].estimate == Approx(0.0).margin(1e-12));
    CHECK(corrected.criteria[2].estimate == Approx(0.0).margin(1e-12));
    CHECK(corrected.overall == stats::Verdict::pass);
    // A control whose offset differs from the wet one leaves the difference: dry coarse = dry fine.
    const DryControl none{ptrs(dry_fine), ptrs(dry_fine)};
    const auto unchanged = judge_ensemble(ptrs(fine), ptrs(coarse), 1.4, 1, tol, 1e-3, true, &none);
    CHECK(unchanged.criteria[0].estimate == Approx(0.12));
    CHECK(unchanged.criteria[2].estimate == Approx(raw.criteria[2].estimate).epsilon(1e-9));
    // The control holds the same seeds or none at all.
    const DryControl short_control{ptrs(dry_fine), {&dry_coarse[0]}};
    CHECK_THROWS_AS(judge_ensemble(ptrs(fine), ptrs(coarse), 1.4, 1, tol, 1e-3, true, &short_control), std::invalid_argument);
}

TEST_CASE("A study whose coarse fill the cone could not hold: that ensemble is UNUSABLE, the others are judged",
          "[slump][verdict][baseline]") {
    StudyPlan plan;
    plan.fine = kantro(), plan.scale_factors = {1.4, 1.96}, plan.exponents = {1}, plan.seeds = 3;
    auto study = plan_study(plan);
    // Every run the same constructed pile (so every comparison is exact), then one coarse fill at
    // S_f 1.96 marked as a pour that jammed.
    const auto same = triangle(0.03, 0.002, 0.02, 0.1);
    for (auto* r : study.all_runs()) r->result = same, r->key = scene_key(r->scene);
    study.coarse_seeds.back().unusable = "fill: the cone holds 37.4 g, short of the fill's 40.49 g";
    judge_study(study, plan);
    REQUIRE(study.corrected.size() == 2);
    CHECK(study.corrected[0].unusable.empty());
    CHECK(study.corrected[0].overall == stats::Verdict::pass);
    REQUIRE(!study.corrected[0].warnings.empty());  // the constructed piles never came to rest: said, not hidden
    CHECK_THAT(study.corrected[0].warnings.back(), Catch::Matchers::Contains("6 of the dry control's 6 piles were still moving"));
    CHECK_THAT(study.corrected[1].unusable, Catch::Matchers::Contains("1 of 6 fills unusable (seed 3: fill: the cone holds 37.4 g"));
    CHECK(study.corrected[1].criteria.empty());
    CHECK(study.overall() == stats::Verdict::pass);  // the unusable ensemble is no part of it
    // One criterion that FAILs on its own but not for the family of 3 criteria judged: the command
    // is INCONCLUSIVE, not FAIL (Holm); far outside, it FAILs.
    auto& slump = study.corrected[0].criteria[0];
    slump.estimate = 0.08, slump.interval = {0.0505, 0.1095}, slump.tolerance = 0.05, slump.verdict = stats::Verdict::fail;
    study.corrected[0].overall = stats::Verdict::fail;
    CHECK(study.family_size() == 3);
    CHECK(study.overall() == stats::Verdict::inconclusive);
    slump.interval = {0.07, 0.09};
    CHECK(study.overall() == stats::Verdict::fail);
    CHECK(study.judged_scale_factors() == std::vector<double>{1.4});
    const auto table = io::render(report::verdict_table(study, "kantro"), io::Format::csv);
    CHECK_THAT(table, Catch::Matchers::Contains("UNUSABLE FILL"));
    CHECK_THAT(io::render(report::study_table(study, "kantro"), io::Format::csv), Catch::Matchers::Contains("UNUSABLE: fill"));
    // A fine fill the cone cannot hold is the scene's problem: refused.
    study.replicas.front().unusable = "fill: short";
    CHECK_THROWS_WITH(judge_study(study, plan), Catch::Matchers::Contains("the fine scene's fill, seed 2"));
}

TEST_CASE("Response curves: levels a factor apart exactly, coarse gamma-bar = f gamma S_f^offset, f = 1 is the study's own run",
          "[slump][exponent]") {
    const auto f = log_spaced_factors(0.25, 4, 5, "--range", "--levels");
    CHECK(f == std::vector<double>{0.25, 0.5, 1, 2, 4});  // exactly: cached runs are found by the scene's bits
    CHECK(log_spaced_factors(0.5, 4, 4, "--range", "--levels") == std::vector<double>{0.5, 1, 2, 4});
    CHECK_THROWS_AS(log_spaced_factors(4, 1, 5, "--range", "--levels"), InputError);
    CHECK_THROWS_AS(log_spaced_factors(0.5, 4, 2, "--range", "--levels"), InputError);

    ResponsePlan plan;
    plan.fine = kantro();
    plan.scale_factors = {1.4, 1.96};
    plan.factors = f;
    plan.offset_exponent = 2;
    plan.seeds = 3;
    const auto study = plan_response_runs(plan);
    const double gamma = plan.fine.liquid.surface_tension_n_per_m, r = plan.fine.radius_m;
    REQUIRE(study.fine.size() == 5);
    REQUIRE(study.coarse.size() == 2);
    for (std::size_t i = 0; i < f.size(); ++i) {
        CHECK(study.fine[i].gamma == f[i] * gamma);
        CHECK(study.fine[i].runs.size() == 3);
        CHECK(study.fine[i].runs[2].scene.seed == plan.fine.seed + 2);
        for (std::size_t s = 0; s < 2; ++s) {
            const double sf = plan.scale_factors[s];
            const auto& run = study.coarse[s][i].runs.front();
            CHECK(run.scene.liquid.surface_tension_n_per_m == Approx(f[i] * gamma * sf * sf).epsilon(1e-14));
            CHECK(run.scene.radius_m == Approx(sf * r).epsilon(1e-14));
            CHECK(run.scene.liquid.moisture_content == plan.fine.liquid.moisture_content);  // V-hat held (Eq. 5)
        }
    }
    // The level f = 1 with the scene's seed is the scene itself: the same cache key as check-exponent's fine run.
    CHECK(scene_key(study.fine[2].runs.front().scene) == scene_key(plan.fine));
    // Dry: one level per S_f, nothing to vary.
    plan.fine.wet = false;
    const auto dry = plan_response_runs(plan);
    CHECK(dry.fine.size() == 1);
    CHECK(dry.coarse.at(1).size() == 1);
}

TEST_CASE("Second look: seeds added to cached ones are named, a rerun or a resumed study is not one", "[slump][study]") {
    // Runs as (seed, from the cache); two runs per seed, as fine and coarse.
    auto batch = [](std::vector<std::pair<unsigned, bool>> spec) {
        std::vector<slump::StudyRun> runs(spec.size());
        for (std::size_t i = 0; i < spec.size(); ++i) runs[i].scene.seed = spec[i].first, runs[i].from_cache = spec[i].second;
        return runs;
    };
    auto look = [](std::vector<slump::StudyRun>& runs) {
        std::vector<slump::StudyRun*> p;
        for (auto& r : runs) p.push_back(&r);
        return slump::second_look(p);
    };
    auto more = batch({{1, true}, {1, true}, {2, true}, {2, true}, {3, false}, {3, false}});
    const auto added = look(more);
    REQUIRE(added.any());
    CHECK(added.earlier == std::vector<unsigned>{1, 2});
    CHECK(added.added == std::vector<unsigned>{3});
    CHECK(added.describe().find("seeds 1-2 came from the cache, seed 3 is new") != std::string::npos);
    auto rerun = batch({{1, true}, {1, true}, {2, true}, {2, true}});
    CHECK_FALSE(look(rerun).any());
    CHECK(look(rerun).describe().empty());
    auto fresh = batch({{1, false}, {2, false}});
    CHECK_FALSE(look(fresh).any());
    // Interrupted and resumed: seed 2 half done before, seed 3 not at all; not more seeds.
    auto resumed = batch({{1, true}, {1, true}, {2, true}, {2, false}, {3, false}, {3, false}});
    CHECK_FALSE(look(resumed).any());
    auto scattered = batch({{5, true}, {9, true}, {7, false}});
    CHECK(look(scattered).describe().find("seeds 5, 9 came from the cache, seed 7 is new") != std::string::npos);
}

TEST_CASE("Verdicts on a runs file: Welch t by hand, the dry twins removed, missing runs refused", "[slump][study][runs]") {
    // Fine slump/height 0.50, 0.52, 0.54 and coarse 0.51, 0.53, 0.55 (γ̄ = γ S_f at k = 1): difference
    // 0.01, both sd 0.02, se = 0.02 sqrt(2/3) = 0.016330, Welch dof 4, t = 2.7764: [-0.035339, 0.055339].
    const double gamma = 0.074, sf = 1.4;
    std::vector<slump::RunRow> rows;
    auto add = [&](double s, double g, long seed, double slump, double spread) { rows.push_back({s, g, seed, slump, spread, true, ""}); };
    for (long i = 0; i < 3; ++i) {
        add(1, gamma, i, 0.50 + 0.02 * static_cast<double>(i), 1.2 + 0.1 * static_cast<double>(i));
        add(sf, gamma * sf, i, 0.51 + 0.02 * static_cast<double>(i), 1.3 + 0.1 * static_cast<double>(i));
        add(sf, gamma * sf * sf, i, 0.2, 1.0);  // k = 2's level: not this ensemble
        add(1, 0, i, 0.70, 1.5);
        add(sf, 0, i, 0.72, 1.5);
    }
    slump::Tolerances tol{0.05, 0.10, 0.15};
    const auto raw = slump::judge_runs(rows, "runs.csv", gamma, 1, {}, tol, slump::Baseline::none);
    REQUIRE(raw.raw.size() == 1);
    REQUIRE_FALSE(raw.has_control());
    const auto& slump = raw.raw[0].criteria.at(0);
    CHECK(slump.estimate == Approx(0.01).margin(1e-15));
    CHECK(slump.interval.low == Approx(-0.035339).margin(2e-6));
    CHECK(slump.interval.high == Approx(0.055339).margin(2e-6));
    CHECK(slump.verdict == stats::Verdict::inconclusive);  // 0.0553 reaches past 0.05
    // Spread relative to the fine mean 1.3: difference 0.1 / 1.3, same se shape (sd 0.1): half-width 0.22665 / 1.3.
    const auto& spread = raw.raw[0].criteria.at(1);
    CHECK(spread.estimate == Approx(0.1 / 1.3).epsilon(1e-12));
    CHECK(spread.interval.high - spread.estimate == Approx(2.7764 * 0.1 * std::sqrt(2.0 / 3) / 1.3).epsilon(1e-4));
    CHECK(raw.raw[0].criteria.size() == 2);  // no profile in a runs file
    CHECK(raw.overall() == stats::Verdict::inconclusive);
    // Against the dry control: each seed less its twin, so the coarse side moves by -0.02.
    const auto corrected = slump::judge_runs(rows, "runs.csv", gamma, 1, {}, tol, slump::Baseline::dry);
    REQUIRE(corrected.has_control());
    CHECK(corrected.corrected[0].criteria[0].estimate == Approx(-0.01).margin(1e-12));
    CHECK(corrected.controls[0].criteria[0].estimate == Approx(0.02).margin(1e-12));
    tol.slump = 0.06;
    CHECK(slump::judge_runs(rows, "runs.csv", gamma, 1, {}, tol, slump::Baseline::none).raw[0].criteria[0].verdict == stats::Verdict::pass);
    // Refused: an S_f without runs at γ S_f^k, and a wet seed without its dry twin.
    CHECK_THROWS_WITH(slump::judge_runs(rows, "runs.csv", gamma, 1, {1.96}, tol, slump::Baseline::none),
                      Catch::Contains("coarse runs at S_f 1.96"));
    CHECK_THROWS_WITH(slump::judge_runs(rows, "runs.csv", gamma, 1.5, {}, tol, slump::Baseline::none), Catch::Contains("k = 1.5"));
    rows.pop_back();  // seed 2's dry coarse run
    CHECK_THROWS_WITH(slump::judge_runs(rows, "runs.csv", gamma, 1, {}, tol, slump::Baseline::dry), Catch::Contains("for seed 2"));
}

TEST_CASE("Sweep's best k carries the exponents the seeds cannot tell from it", "[slump][study]") {
    // Profile distances at S_f 1.4 (estimate [interval]): k 1: 6 [4, 9], k 1.5: 8 [5, 11], k 2: 12 [9.5, 15],
    // k 3: 30 [25, 35]. The best is k 1; k 1.5's interval reaches 5 < 9 (overlap), k 2's starts at 9.5 > 9.
    slump::Study study;
    auto verdict = [](double sf, double k, double d, double lo, double hi) {
        slump::EnsembleVerdict v;
        v.sf = sf, v.exponent = k;
        auto criterion = [](const char* measure, double estimate, stats::Interval ci, double tolerance) {
            slump::Criterion c;
            c.measure = measure, c.estimate = estimate, c.interval = ci, c.tolerance = tolerance;
            return c;
        };
        v.criteria = {criterion("slump", 0, {-0.01, 0.01}, 0.05), criterion("spread", 0, {-0.01, 0.01}, 0.1),
                      criterion("profile", d, {lo, hi}, 0.15)};
        return v;
    };
    study.verdicts = {verdict(1.4, 1, 0.06, 0.04, 0.09), verdict(1.4, 1.5, 0.08, 0.05, 0.11), verdict(1.4, 2, 0.12, 0.095, 0.15),
                      verdict(1.4, 3, 0.30, 0.25, 0.35), verdict(1.96, 1, 0.2, 0.1, 0.3), verdict(1.96, 2, 0.1, 0.08, 0.12)};
    CHECK(study.best_at(1.4).exponent == 1);
    CHECK(study.not_told_apart_from_best(1.4) == std::vector<double>{1.5});
    CHECK(study.best_at(1.96).exponent == 2);
    CHECK(study.not_told_apart_from_best(1.96) == std::vector<double>{1});  // 0.1 <= 0.12
    const auto t = report::best_exponent_table(study, {1.4, 1.96});
    REQUIRE(t.rows.size() == 2);
    CHECK(std::get<std::string>(t.rows[0][5]) == "k = 1.5");
}
