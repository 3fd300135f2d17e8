// The spatial sort: the Z-order curve by hand, and an engine that reorders its spheres running
// the same physics as one that does not (to rounding), restarting and threading bit for bit.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <omp.h>
#include <random>
#include <sstream>

#include "bridge/mikami.hpp"
#include "dem/simulation.hpp"
#include "slump/shared_engines.hpp"  // the library's copies of the engines it shares

using namespace demscale;
using namespace demscale::dem;

TEST_CASE("Spatial order: cell by cell, rows along x, then y, then layers in z, by hand", "[dem][sort]") {
    // Eight spheres at the centres of a 2 x 2 x 2 block of cells, given in reverse order, plus two
    // that share the first cell (ties keep their index order). Cell (x, y, z) comes at x + 2y + 4z.
    const double cell = 1.0;
    Particles p;
    for (int k = 7; k >= 0; --k) p.add(Vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1) + Vec3::Constant(0.5), 0.1, 1000);
    p.add(Vec3(0.2, 0.2, 0.2), 0.1, 1000);  // index 8, cell (0,0,0)
    p.add(Vec3(0.9, 0.1, 0.3), 0.1, 1000);  // index 9, cell (0,0,0)
    const std::vector<std::uint32_t> expected{7, 8, 9, 6, 5, 4, 3, 2, 1, 0};
    CHECK(spatial_order(p, cell) == expected);

    // A 3 x 3 x 2 grid (from the lowest to the highest sphere): cell (x, y, z) at x + 3y + 9z.
    Particles q;
    q.add(Vec3(2.5, 0.5, 0.5), 0.1, 1000);  // (2,0,0): 2
    q.add(Vec3(1.5, 1.5, 1.5), 0.1, 1000);  // (1,1,1): 13
    q.add(Vec3(0.5, 2.5, 0.5), 0.1, 1000);  // (0,2,0): 6
    q.add(Vec3(0.5, 0.5, 0.5), 0.1, 1000);  // (0,0,0): 0
    CHECK(spatial_order(q, cell) == std::vector<std::uint32_t>{3, 0, 2, 1});
}

TEST_CASE("Spatial order: layers along the longest side, rows along the lower of the other two axes", "[dem][sort]") {
    // The 3 x 3 x 2 grid above with one sphere more; the box around the centres is 2 x 2 x 1: x and
    // y tie, and the first of equal sides counts as the longest. Layers along x, rows along y, row
    // after row along z: cell (x, y, z) at y + 3z + 6x.
    const double cell = 1.0;
    Particles q;
    q.add(Vec3(2.5, 0.5, 0.5), 0.1, 1000);  // (2,0,0): 12
    q.add(Vec3(1.5, 1.5, 1.5), 0.1, 1000);  // (1,1,1): 10
    q.add(Vec3(0.5, 2.5, 0.5), 0.1, 1000);  // (0,2,0): 2
    q.add(Vec3(0.5, 0.5, 0.5), 0.1, 1000);  // (0,0,0): 0
    q.add(Vec3(0.5, 0.5, 1.5), 0.1, 1000);  // (0,0,1): 3
    CHECK(longest_side(q) == 0);
    CHECK(spatial_order(q, cell, 0) == std::vector<std::uint32_t>{3, 2, 4, 1, 0});
    // Layers along y, rows along x, row after row along z: x + 3z + 6y.
    // (2,0,0) 2, (1,1,1) 10, (0,2,0) 12, (0,0,0) 0, (0,0,1) 3.
    CHECK(spatial_order(q, cell, 1) == std::vector<std::uint32_t>{3, 0, 4, 1, 2});
    // Along z, as by default: x + 3y + 9z: 2, 13, 6, 0, 9.
    CHECK(spatial_order(q, cell, 2) == spatial_order(q, cell));
    CHECK(spatial_order(q, cell) == std::vector<std::uint32_t>{3, 0, 2, 4, 1});
    // A tall column: z the longest side; none at all: z.
    Particles column;
    column.add(Vec3(0, 0, 0), 0.1, 1000), column.add(Vec3(0.5, 0.2, 3), 0.1, 1000);
    CHECK(longest_side(column) == 2);
    CHECK(longest_side(Particles{}) == 2);
}

namespace {

using Wet = ContactLaw<NormalHertz, TangentialMindlin, CohesionLiquidBridge, RollingEpsd>;

// A wet bed falling into a cone on a floor: pairs with tangential and rolling springs, bridges
// across gaps, contacts with both walls. Spheres in random order (as a pour leaves them).
struct Bed {
    Particles spheres;
    std::vector<Wall> walls;
    Wet law;
};

Bed wet_bed(unsigned seed) {
    const double r = 1e-3;
    Material m;
    m.friction = 0.5;
    m.rolling_friction = 0.1;
    m.youngs_modulus = 5e6;
    Bed bed{{}, {}, Wet(m, CohesionLiquidBridge{bridge::mikami_coefficients(0.05544, ContactAngle{Degrees{0}}), r, 0.074, std::nullopt})};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    std::vector<Vec3> sites;
    for (int a = -6; a <= 6; ++a)
        for (int b = -6; b <= 6; ++b)
            for (int c = 0; c < 10; ++c)
                if (std::hypot(a, b) <= 6) sites.push_back(2.1 * r * Vec3(a, b, c) + Vec3(0, 0, 1.2 * r));
    std::shuffle(sites.begin(), sites.end(), rng);
    for (const auto& x : sites) bed.spheres.add(x, r * (1 + 0.1 * u(rng)), 2500, Vec3(u(rng), u(rng), u(rng)));
    FrustumWall cone;
    cone.bottom_radius = 15 * r, cone.top_radius = 14 * r, cone.height = 40 * r;
    bed.walls = {PlaneWall{}, cone};
    return bed;
}

constexpr SpatialSort never{std::size_t(-1), 0};
constexpr SpatialSort often{0, 150};  // every 150 steps, however small the scene

}  // namespace

TEST_CASE("An engine that reorders its spheres runs the same physics, and names them in the input's order", "[dem][sort]") {
    const Bed bed = wet_bed(4);
    const double dt = 2e-6, skin = 0.1e-3;
    Simulation<Wet, false> plain(bed.spheres, bed.law, bed.walls, Vec3(0, 0, -9.81), dt, skin, never);
    Simulation<Wet, false> sorted(bed.spheres, bed.law, bed.walls, Vec3(0, 0, -9.81), dt, skin, often);
    // The first sort at the first build: the order is no longer the input's.
    std::vector<std::uint32_t> identity(bed.spheres.size());
    std::iota(identity.begin(), identity.end(), 0u);
    CHECK(sorted.input_index() != identity);
    CHECK(plain.input_index() == identity);
    double bridge_energy = 0;
    for (int n = 0; n < 3000; ++n) {
        plain.step(), sorted.step();
        if (n % 500 == 0) bridge_energy = std::min(bridge_energy, plain.energy().stored.bridge);
    }
    CHECK(sorted.spatial_sorts() >= 10);
    CHECK(plain.spatial_sorts() == 0);
    CHECK(bridge_energy < 0);  // bridges acted

    // input_index is a permutation, and in_input_order() puts every sphere back where it was given.
    std::vector<std::uint32_t> seen = sorted.input_index();
    std::sort(seen.begin(), seen.end());
    CHECK(seen == identity);
    const Particles a = plain.in_input_order(), b = sorted.in_input_order();
    CHECK(a.radius == bed.spheres.radius);
    CHECK(b.radius == bed.spheres.radius);
    // The spheres moved (up to 2 mm) and touched: only the order in which each sphere sums its
    // forces differs, so the two runs part at rounding level. A contact history that did not
    // follow its sphere (pairs, walls) would part them by the contact forces themselves.
    double moved = 0, apart = 0, spin_apart = 0, spin = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        moved = std::max(moved, (a.position[i] - bed.spheres.position[i]).norm());
        apart = std::max(apart, (a.position[i] - b.position[i]).norm());
        spin = std::max(spin, a.angular_velocity[i].norm());
        spin_apart = std::max(spin_apart, (a.angular_velocity[i] - b.angular_velocity[i]).norm());
    }
    CHECK(moved > 5e-5);
    CHECK(spin > 1);  // rad/s: the tangential and rolling springs act
    INFO("moved " << moved << " m, apart " << apart << " m, spin " << spin << " rad/s, spin apart " << spin_apart);
    CHECK(apart < 1e-14);            // seen: 1.2e-16 m
    CHECK(spin_apart < 1e-9 * spin);  // seen: 2e-12 of it
}

TEST_CASE("A reordering engine restarts from its checkpoint and runs on any thread count bit for bit", "[dem][sort][restart][threads]") {
    const Bed bed = wet_bed(8);
    const double dt = 2e-6, skin = 0.1e-3;
    auto make = [&](const Particles& p) { return Simulation<Wet, false>(p, bed.law, bed.walls, Vec3(0, 0, -9.81), dt, skin, often); };
    omp_set_num_threads(1);
    auto straight = make(bed.spheres);
    for (int n = 0; n < 1200; ++n) straight.step();

    omp_set_num_threads(2);
    auto first = make(bed.spheres);
    for (int n = 0; n < 700; ++n) first.step();  // past four sorts, between two
    std::stringstream checkpoint;
    first.save(checkpoint);
    auto resumed = make(Particles{});
    resumed.load(checkpoint);
    for (int n = 0; n < 500; ++n) resumed.step();
    omp_set_num_threads(omp_get_num_procs());

    REQUIRE(straight.spatial_sorts() == resumed.spatial_sorts());
    CHECK(straight.input_index() == resumed.input_index());
    const auto& a = straight.particles();
    const auto& b = resumed.particles();
    CHECK(std::memcmp(a.position.data(), b.position.data(), a.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(a.angular_velocity.data(), b.angular_velocity.data(), a.size() * sizeof(Vec3)) == 0);
}
