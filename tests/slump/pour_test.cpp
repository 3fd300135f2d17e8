// The poured fill, the fill measures and the rest criterion: insertion without overlaps inside the
// cone, the cut to the fill's mass, the solid fraction of a poured dry fill against the random loose-to-dense
// packing range, measures against constructed lattices (hand counts, closed-form fractions), and a
// damped scene that comes to rest by the quantile criterion.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include "slump/fill.hpp"
#include "slump/fill_measures.hpp"
#include "slump/motion.hpp"
#include "slump/pour.hpp"
#include "slump/slump_run.hpp"
#include "sampling_error.hpp"

using namespace demscale;
using namespace demscale::slump;

namespace {
// A wide, short cone whose core (one diameter from every boundary) holds many spheres.
SlumpScene wide_cone(bool wet) {
    SlumpScene s;
    s.bottom_diameter_m = 0.040, s.top_diameter_m = 0.036, s.height_m = 0.030;
    s.radius_m = 1.5e-3, s.fill_height_m = 0.025;
    s.material.rolling_damping = 0.3;
    s.wet = wet;
    s.dt_s = 2e-5, s.skin_m = 0.45e-3, s.settle_time_s = 0.3;
    return s;
}
}  // namespace

TEST_CASE("Insertion: the asked count, no overlaps, inside the cone and its top column, reproducible from the seed", "[slump][pour]") {
    const auto s = wide_cone(false);
    const auto pile = insert_batch(s, {}, 300, 0);
    const auto more = insert_batch(s, pile, 200, 1);
    REQUIRE(pile.size() == 300);
    REQUIRE(more.size() == 200);
    dem::Particles all = pile;
    all.append(more);
    double closest = 1e300, lowest_new = 1e300, highest_old = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const auto& x = all.position[i];
        CHECK(std::hypot(x.x(), x.y()) + s.radius_m <= cone_radius_at(s, std::min(x.z(), s.height_m)) + 1e-12);
        CHECK(x.z() >= s.radius_m);
        for (std::size_t j = 0; j < i; ++j) closest = std::min(closest, (x - all.position[j]).norm());
        if (i < 300) highest_old = std::max(highest_old, x.z() + s.radius_m);
        else lowest_new = std::min(lowest_new, x.z() - s.radius_m);
    }
    CHECK(closest >= 2 * s.radius_m);
    CHECK(lowest_new > highest_old);  // a batch goes above the pile
    const auto again = insert_batch(s, {}, 300, 0);
    CHECK(again.position[123] == pile.position[123]);
    auto other = s;
    other.seed = 2;
    CHECK(insert_batch(other, {}, 300, 0).position[123] != pile.position[123]);
}

TEST_CASE("Cut to mass: the lowest centres inside the cone, to the fill's mass within half a sphere, short fills refused",
          "[slump][pour]") {
    const auto s = wide_cone(false);
    const double r = s.radius_m, m = s.material.density * 4.0 / 3.0 * M_PI * r * r * r;
    // A helix of spheres, one through the wall and one outside: by hand, the target ρ φ V (V the
    // frustum below the fill height, radii 20 mm at the floor and 20 − 2 × 25/30 mm there) is so many
    // spheres; the lowest that many are kept.
    const double r0 = 0.020, rz = 0.020 - 0.002 * 0.025 / 0.030, target = s.material.density * 0.5 * M_PI * 0.025 * (r0 * r0 + r0 * rz + rz * rz) / 3;
    CHECK(fill_mass(s) == Approx(target));
    const auto want = static_cast<std::size_t>(std::floor(target / m + 0.5));
    dem::Particles p;
    p.add({0.0195, 0, 0.002}, r, s.material.density);  // through the wall: never kept
    p.add({0.030, 0, r}, r, s.material.density);       // outside: never kept
    for (std::size_t i = 0; i < want + 40; ++i) {     // a helix, clear of the wall, rising 0.015 R a sphere
        const double a = 0.7 * static_cast<double>(i), z = r + 0.015 * r * static_cast<double>(want + 40 - i);
        p.add({0.012 * std::cos(a), 0.012 * std::sin(a), z}, r, s.material.density);
    }
    const auto kept = cut_to_mass(s, p);
    REQUIRE(kept.size() == want);
    double mass = 0, highest = 0;
    for (std::size_t i = 0; i < kept.size(); ++i) mass += kept.mass[i], highest = std::max(highest, kept.position[i].z());
    CHECK(std::abs(mass - target) <= 0.5 * m);
    CHECK(highest == Approx(r + 0.015 * r * static_cast<double>(want)));  // the 40 highest went
    // A sphere whose top pokes above the cone's rim is still held by the wall below its centre: the
    // helix raised so that the highest of the `want` lowest pokes R/2 above the rim keeps them all.
    auto raised = p;
    const double dz = s.height_m - 0.5 * r - (r + 0.015 * r * static_cast<double>(want));
    for (std::size_t i = 2; i < raised.size(); ++i) raised.position[i].z() += dz;
    CHECK(cut_to_mass(s, raised).size() == want);
    // Fewer spheres than the target: refused, naming the radius and the shortfall.
    dem::Particles few;
    few.add({0, 0, r}, r, s.material.density);
    CHECK_THROWS_WITH(cut_to_mass(s, few), Catch::Contains("short of the fill") && Catch::Contains("1.5 mm"));
}

TEST_CASE("Fill measures of constructed lattices: closed-form solid fraction, hand-counted contacts", "[slump][fill]") {
    auto s = wide_cone(false);
    s.fill = FillKind::lattice;
    SECTION("the jittered hcp lattice of fill_cone: core fraction pi / (3 sqrt 2) / 1.01^3, no contacts") {
        const auto m = measure_fill(fill_cone(s), s);
        CHECK(m.core_points > 10000);
        CHECK(m.core_fraction == Approx(M_PI / (3 * std::sqrt(2.0)) / std::pow(1.01, 3)).epsilon(0.01));
        CHECK(m.coordination == 0);  // 2 % gaps
        CHECK(m.max_overlap == 0);
    }
    SECTION("a simple cubic lattice of pitch 1.99 R: core fraction pi / 6 / 0.995^3; contacts counted pair by pair") {
        dem::Particles p;
        const double r = s.radius_m, a = 1.99 * r;
        for (int i = -12; i <= 12; ++i)
            for (int j = -12; j <= 12; ++j)
                for (int k = 0; k < 12; ++k) {
                    const dem::Vec3 x(i * a, j * a, r + k * a);
                    if (std::hypot(x.x(), x.y()) + r < cone_radius_at(s, x.z()) && x.z() + r <= s.fill_height_m) p.add(x, r, 2500);
                }
        std::size_t pairs = 0;  // brute force, the independent count
        for (std::size_t i = 0; i < p.size(); ++i)
            for (std::size_t j = 0; j < i; ++j) pairs += (p.position[i] - p.position[j]).norm() <= 2 * r;
        const auto m = measure_fill(p, s);
        CHECK(m.coordination == Approx(2.0 * double(pairs) / double(p.size())));
        CHECK(m.coordination > 4.5);  // 6 inside, fewer at the boundary
        CHECK(m.max_overlap == Approx(0.01).epsilon(1e-6));
        CHECK(m.core_fraction == Approx(M_PI / 6 / std::pow(0.995, 3)).epsilon(0.01));
    }
}

TEST_CASE("Rest criterion: a quantile of the speeds, so one rattler cannot veto rest", "[slump][rest]") {
    dem::Particles p;
    for (int i = 0; i < 200; ++i) p.add({0.01 * i, 0, 0}, 1e-3, 2500, dem::Vec3(0, 0, 1e-4));
    CHECK(quantile_slower_than(p, p.size(), 1e-3, 0.99));
    p.velocity[17] = {0.5, 0, 0};  // one rattler (0.5 % of 200)
    CHECK(quantile_slower_than(p, p.size(), 1e-3, 0.99));
    CHECK_FALSE(quantile_slower_than(p, p.size(), 1e-3, 1.0));  // "every particle": vetoed
    p.velocity[18] = {0, 0.5, 0}, p.velocity[19] = {0, 0, -0.5};  // 1.5 %: the pile moves
    CHECK_FALSE(quantile_slower_than(p, p.size(), 1e-3, 0.99));
    const auto m = summarize_motion(p, p.size(), 1e-3);
    CHECK(m.moving == 3);
    CHECK(m.speed_max == Approx(0.5));
    CHECK(m.speed_p50 == Approx(1e-4));
}

TEST_CASE("Poured dry fill: random loose-to-dense packing in the core, small overlaps, comes to rest, then the pile rests too",
          "[slump][pour][slow]") {
    auto s = wide_cone(false);
    s.spread_time_s = 0.4, s.lift_height_m = 0.035, s.rest_duration_s = 0.02;
    const auto r = run_slump(s);
    INFO("core " << r.fill.core_fraction << ", bulk " << r.fill.solid_fraction << ", Z " << r.fill.coordination << ", overlap "
                 << r.fill.max_overlap << ", pour " << r.pour_time << " s, " << r.particles << " spheres");
    // Monodisperse frictional spheres poured under gravity: between random loose (0.55) and random
    // close packing (0.64) away from the walls; the wall layer and the rough top make the bulk looser.
    CHECK(r.fill.core_fraction > 0.55);
    CHECK(r.fill.core_fraction < 0.64);
    CHECK(r.fill.solid_fraction < r.fill.core_fraction);
    CHECK(r.fill.max_overlap < 0.05);          // Hertz at this weight: about 1 % of R
    CHECK(r.fill.coordination > 3.0);          // frictional packings: 4-6 (rattlers lower the mean)
    CHECK(r.fill.coordination < 7.0);
    CHECK(r.fill.mass == Approx(fill_mass(s)).margin(0.5 * s.material.density * 4.0 / 3.0 * M_PI * std::pow(s.radius_m, 3)));
    CHECK(r.pour_time > 0);
    CHECK(r.settled);                          // the struck-off fill rests before the lift
    CHECK(r.came_to_rest);                     // with the rolling dashpot the pile rests too
    CHECK(r.time_to_rest() > 0);
    CHECK(r.time_to_rest() < s.spread_time_s);
    CHECK(r.motion.speed_p99 < s.rest_speed_m_per_s);
}

TEST_CASE("Poured wet fill of a sieve table: each class's share of the mass, the pile rests, the ledger balances",
          "[slump][pour][sizes][slow]") {
    auto s = wide_cone(true);
    s.sizes.class_ratios = {0.7, 1.0, 1.4};
    s.sizes.mass_fractions = {0.25, 0.5, 0.25};
    s.spread_time_s = 0.4, s.lift_height_m = 0.035, s.rest_duration_s = 0.02;
    s.dt_s = 1.4e-5;  // the smallest spheres' time step (0.7 R)
    SlumpPhases phases;
    phases.energy_ledger = true;
    const auto r = run_slump(s, {}, false, phases);
    const auto& p = r.final_state;
    std::vector<double> mass(3, 0.0);
    double total = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double x = p.radius[i] / s.radius_m;
        const auto c = static_cast<std::size_t>(std::min_element(s.sizes.class_ratios.begin(), s.sizes.class_ratios.end(),
                                                                 [&](double a, double b) { return std::abs(a - x) < std::abs(b - x); }) -
                                                s.sizes.class_ratios.begin());
        REQUIRE(std::abs(s.sizes.class_ratios[c] - x) < 1e-12);
        mass[c] += p.mass[i], total += p.mass[i];
    }
    // The fill's mass is the scene's, within half of the largest sphere.
    CHECK(total == Approx(fill_mass(s)).margin(0.5 * s.material.density * 4.0 / 3.0 * M_PI * std::pow(1.4 * s.radius_m, 3)));
    // Each class within 4 standard errors of a draw of this many spheres (the delta method, as
    // sampling_error.hpp), and within one of its spheres of its share of the fill's mass:
    // the cut keeps each class's share (a single cut level kept 0.16-0.21 of the mass in the largest
    // class instead of 0.25, in 5 seeds: large spheres settle high and against the wall).
    const double n = static_cast<double>(p.size());
    for (std::size_t c = 0; c < 3; ++c) {
        const double error = class_mass_fraction_error(s.sizes.class_ratios, s.sizes.mass_fractions, c, n);
        INFO("class " << c << ": " << mass[c] / total << " of the mass, +- " << error << " (" << n << " spheres)");
        CHECK(std::abs(mass[c] / total - s.sizes.mass_fractions[c]) < 4 * error);
        CHECK(std::abs(mass[c] - s.sizes.mass_fractions[c] * fill_mass(s)) <=
              s.material.density * 4.0 / 3.0 * M_PI * std::pow(s.sizes.class_ratios[c] * s.radius_m, 3));
    }
    CHECK(r.settled);
    CHECK(r.came_to_rest);
    INFO("energy balance error " << r.energy_balance_error());
    CHECK(std::abs(r.energy_balance_error()) < 0.03);  // conservation of energy, as the monodisperse wet run (cli_test.sh)
}
