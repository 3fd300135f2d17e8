// The size sweep's pieces: the scaled cone by hand, the packed start (neighbours touching, by
// brute-force distances; the shuffled one the same spheres in another order), and the timing's
// step accounting on a tiny size.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "slump/size_sweep.hpp"

using namespace demscale;
using namespace demscale::slump;

namespace {
SlumpScene small() { return load_slump_scene(DEMSCALE_SOURCE_DIR "/data/scenes/small_wet.toml"); }
}  // namespace

TEST_CASE("Size sweep: every length of the cone and fill scales, the sphere does not", "[slump][size_sweep]") {
    const auto s = small();
    const auto t = scaled_cone(s, 2.5);
    CHECK(t.bottom_diameter_m == Approx(2.5 * s.bottom_diameter_m));
    CHECK(t.top_diameter_m == Approx(2.5 * s.top_diameter_m));
    CHECK(t.height_m == Approx(2.5 * s.height_m));
    CHECK(t.fill_height_m == Approx(2.5 * s.fill_height_m));
    CHECK(t.lift_height_m == Approx(2.5 * s.lift_height_m));
    CHECK(t.radius_m == s.radius_m);
    CHECK(t.dt_s == s.dt_s);
}

TEST_CASE("Size sweep: the packed start touches (pitch 2R), shuffled is a permutation", "[slump][size_sweep]") {
    const auto s = small();
    const auto p = packed_fill(s, false);
    REQUIRE(p.size() > 50);
    const double r = s.radius_m;
    // Nearest neighbour of each sphere, brute force: 2R within the fill's jitter (±0.5 % R per axis).
    double lo = 1e9, hi = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        double nearest = 1e9;
        for (std::size_t j = 0; j < p.size(); ++j)
            if (j != i) nearest = std::min(nearest, (p.position[i] - p.position[j]).norm());
        lo = std::min(lo, nearest), hi = std::max(hi, nearest);
    }
    CHECK(lo > 2 * r * (1 - 0.02));
    CHECK(hi < 2 * r * (1 + 0.02));
    const auto q = packed_fill(s, true);
    REQUIRE(q.size() == p.size());
    auto key = [](const dem::Vec3& x) { return std::make_tuple(x.x(), x.y(), x.z()); };
    std::set<std::tuple<double, double, double>> a, b;
    for (const auto& x : p.position) a.insert(key(x));
    for (const auto& x : q.position) b.insert(key(x));
    CHECK(a == b);
    CHECK(p.position[0] != q.position[0]);
}

TEST_CASE("Size sweep: a tiny point times 2N steps of about the asked size, repeated for the asked work", "[slump][size_sweep]") {
    const auto point = time_size(small(), 300, 10, true, 0);
    CHECK(point.particles > 250);
    CHECK(point.particles < 350);
    CHECK(point.steps == 20);  // one pair: 30 less 10
    // Timed, or, when the set-up's noise exceeded 20 steps of 300 spheres, said to be untimed.
    if (point.wall_s > 0) {
        CHECK(point.particle_steps_per_s == Approx(double(point.particles) * 20 / point.wall_s));
        CHECK(point.contact_steps_per_s == Approx(point.particle_steps_per_s * point.contacts_per_particle));
    } else {
        CHECK(point.particle_steps_per_s == 0);
    }
    // A packed bed under gravity: every sphere presses on some below it (12 at most, 6 per pair).
    CHECK(point.contacts_per_particle > 0.5);
    CHECK(point.contacts_per_particle <= 6);
    // Three pairs asked for by the work: 3 × (3·10 − 10) steps.
    const auto repeated = time_size(small(), 300, 10, true, 2.5 * 20 * double(point.particles));
    CHECK(repeated.steps == 60);
}

TEST_CASE("Size sweep: contacts per particle are the overlapping pairs, by hand and by brute force", "[slump][size_sweep]") {
    dem::Particles row;  // a row of four: 1-2 overlap by 0.1 mm, 2-3 and 3-4 apart by 0.1 mm
    const double r = 1e-3;
    row.add({0, 0, 0}, r, 2500), row.add({1.9e-3, 0, 0}, r, 2500), row.add({4.0e-3, 0, 0}, r, 2500), row.add({6.1e-3, 0, 0}, r, 2500);
    CHECK(contacts_per_particle(row) == Approx(1.0 / 4));
    CHECK(contacts_per_particle(dem::Particles{}) == 0);
    // The packed start pressed together by 1 %: every pair closer than 2R by brute force.
    auto p = packed_fill(small(), false);
    for (auto& x : p.position) x *= 0.99;
    std::size_t brute = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j) brute += (p.position[i] - p.position[j]).norm() < p.radius[i] + p.radius[j];
    REQUIRE(brute > p.size());
    CHECK(contacts_per_particle(p) == Approx(double(brute) / double(p.size())).epsilon(1e-12));
}
