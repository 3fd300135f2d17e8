// Analytic walls: closest points against hand geometry, motion windows, and a bounce.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "dem/simulation.hpp"
#include "slump/shared_engines.hpp"  // the library's copies of the engines it shares

using namespace demscale::dem;

TEST_CASE("Frustum wall: closest point and distance from meridian geometry", "[dem][walls]") {
    // Kantro cone: r_b = 19 mm, r_t = 9.5 mm, H = 57 mm. For a point at (rho, z) whose projection falls
    // inside the segment, the distance to the surface is |(rho - r_b) H - z (r_t - r_b)| / sqrt(H^2 + (r_t - r_b)^2).
    const FrustumWall cone{};
    const double dr = -0.0095, H = 0.057, L = std::hypot(dr, H);
    for (double rho : {0.0, 0.005, 0.015, 0.03})
        for (double z : {0.01, 0.03}) {
            const Vec3 x(rho * std::cos(0.7), rho * std::sin(0.7), z);
            const auto wp = closest_wall_point(cone, x, 0.0);
            const double expected = std::abs((rho - 0.019) * H - z * dr) / L;
            INFO("rho=" << rho << " z=" << z);
            CHECK((x - wp.point).norm() == Approx(expected).epsilon(1e-12));
            CHECK_FALSE(wp.behind);
        }
    // Beyond the rims the closest point is the rim itself.
    const auto above = closest_wall_point(cone, Vec3(0, 0, 0.1), 0.0);
    CHECK(above.point.z() == Approx(0.057));
    CHECK(std::hypot(above.point.x(), above.point.y()) == Approx(0.0095));
    // A cylinder is a frustum with equal radii: distance |R - rho|.
    const FrustumWall cylinder{Vec3::Zero(), 0.01, 0.01, 0.05, Vec3::Zero(), 0, 0};
    CHECK((Vec3(0.004, 0.003, 0.02) - closest_wall_point(cylinder, Vec3(0.004, 0.003, 0.02), 0).point).norm() ==
          Approx(0.005).epsilon(1e-12));
}

TEST_CASE("Frustum wall moves only inside its time window", "[dem][walls]") {
    FrustumWall cone{};
    cone.velocity = Vec3(0, 0, 0.3);
    cone.move_start = 0.1;
    cone.move_end = 0.1 + 0.065 / 0.3;  // lifted 65 mm at 0.3 m/s
    CHECK(cone.offset(0.05).norm() == 0.0);
    CHECK(cone.offset(0.2).z() == Approx(0.03));
    CHECK(cone.offset(10).z() == Approx(0.065));
    CHECK(cone.velocity_at(0.2).z() == 0.3);
    CHECK(cone.velocity_at(0.5).norm() == 0.0);
    const auto wp = closest_wall_point(cone, Vec3(0, 0, 0.2 + 0.03), 10.0);
    CHECK(wp.point.z() == Approx(0.057 + 0.065));
}

TEST_CASE("A sphere bounces off a cylinder wall with the law's restitution", "[dem][walls]") {
    Material m;
    m.linear_stiffness = 1e3;
    m.restitution = 0.6;
    const double r = 1e-3;
    Particles p;
    p.add({0.005, 0, 0.02}, r, 2500, {0.2, 0, 0});
    const FrustumWall cylinder{Vec3::Zero(), 0.01, 0.01, 0.05, Vec3::Zero(), 0, 0};
    Simulation sim(p, ContactLaw<NormalLinear>(m), {cylinder}, Vec3::Zero(), 1e-6, 0.1 * r);
    for (int n = 0; n < 40000 && sim.particles().velocity[0].x() > -0.1; ++n) sim.step();
    for (int n = 0; n < 2000; ++n) sim.step();  // well clear of the wall
    CHECK(sim.particles().velocity[0].x() == Approx(-0.6 * 0.2).epsilon(0.005));
}

TEST_CASE("The engine's cheap wall bound agrees with the exact distance, on the safe side", "[dem][walls]") {
    // WallBound lets the engine skip particles no wall reaches. It must never skip one
    // within reach (a missed contact), and must skip the far ones (or it saves nothing). For random
    // centres around a moving cone, a cylinder and a tilted plane, at their exact distance e
    // (closest_wall_point): false at e itself, true a millionth below it.
    FrustumWall lifted{};
    lifted.velocity = Vec3(0, 0, 0.3);
    lifted.move_end = 0.2;
    const FrustumWall cylinder{Vec3(0.001, -0.002, 0), 0.01, 0.01, 0.05, Vec3::Zero(), 0, 0};
    const PlaneWall tilted{Vec3(0, 0, -0.005), Vec3(0.3, -0.2, 1).normalized()};
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.04, 0.04), height(-0.004, 0.1);
    for (const Wall& wall : {Wall(lifted), Wall(cylinder), Wall(tilted)}) {
        int far = 0;
        for (int n = 0; n < 20000; ++n) {
            const Vec3 x(u(rng), u(rng), height(rng));
            const double t = 0.1;
            const WallPoint wp = closest_wall_point(wall, x, t);
            if (wp.behind) continue;
            const double e = (x - wp.point).norm();
            INFO("wall " << wall.index() << ", centre " << x.transpose() << ", distance " << e);
            const WallBound bound(wall, t);
            REQUIRE_FALSE(bound.surely_farther_than(x, e));
            REQUIRE(bound.surely_farther_than(x, e * (1 - 1e-6)));
            const bool skipped = bound.surely_farther_than(x, 1.37e-3);
            REQUIRE(skipped == (e > 1.37e-3 * (1 + 1e-9)));
            far += skipped;
        }
        CHECK(far > 10000);
    }
}

TEST_CASE("A wall sweeping towards a resting sphere meets it where the geometry says", "[dem][walls]") {
    // The engine looks only at spheres near a wall, marked when the neighbour list is built. A
    // sphere at rest never triggers a rebuild, so the marks must follow the wall itself: a cylinder
    // (radius 10 mm) driven at 2 m/s along x towards a sphere (r = 1 mm, centre 20.001 mm from its
    // axis) crosses 9 mm, 180 skins, before touching it. Hand geometry: the first force acts at the
    // first step whose time t (a step's forces use the time at its start) has 10 mm + v t > x - r,
    // half a step's travel away from any rounding.
    Material m;
    m.linear_stiffness = 1e3;
    const double r = 1e-3, v = 2, dt = 1e-6;
    Particles p;
    p.add({0.020001, 0, 0.02}, r, 2500, Vec3::Zero());
    const FrustumWall sweeping{Vec3::Zero(), 0.01, 0.01, 0.05, Vec3(v, 0, 0), 0, 1};
    Simulation sim(p, ContactLaw<NormalLinear>(m), {sweeping}, Vec3::Zero(), dt, 0.05 * r);
    long first_push = -1;
    for (long n = 0; n < 6000 && first_push < 0; ++n) {
        sim.step();
        if (sim.particles().force[0].norm() > 0) first_push = n;
    }
    const double touch = (0.020001 - r - 0.01) / v;  // s
    CHECK(first_push == static_cast<long>(std::floor(touch / dt)) + 1);
    CHECK(sim.particles().force[0].x() > 0);
}

TEST_CASE("A wall moved by hand between steps acts at once", "[dem][walls]") {
    // A floor 9 mm below a resting sphere's bottom is not near it; moved by hand to cut 0.4 mm into
    // the sphere, it pushes with k δ at the next force evaluation (hand value), though the sphere
    // has not moved and the neighbour list is not rebuilt.
    Material m;
    m.linear_stiffness = 1e3;
    const double r = 1e-3;
    Particles p;
    p.add({0, 0, 0.005}, r, 2500, Vec3::Zero());
    Simulation sim(p, ContactLaw<NormalLinear>(m), {PlaneWall{Vec3(0, 0, -0.005), Vec3::UnitZ()}}, Vec3::Zero(), 1e-6, 0.05 * r);
    sim.step();
    CHECK(sim.particles().force[0].norm() == 0.0);
    sim.walls()[0] = PlaneWall{Vec3(0, 0, 0.005 - r + 0.4e-3), Vec3::UnitZ()};
    sim.refresh_forces();
    CHECK(sim.particles().force[0].z() == Approx(1e3 * 0.4e-3).epsilon(1e-9));
}

TEST_CASE("Without the ledger every sphere near a wall gets its force on any thread count", "[dem][walls][threads]") {
    // Without the ledger the threads split only the spheres marked near a wall, by their work. 600
    // spheres (r = 1 mm, 3 mm apart, none touching another) cut 0.4 mm into a wall at x = 0, and
    // beside each, 50 mm out along x, a sphere far from it: in the engine's order (rows along x)
    // the marked spheres are every other one, 600 of them, enough for the loop to run threaded.
    // Hand values: a sphere at the wall is pushed out with k δ, one far from it feels nothing.
    Material m;
    m.linear_stiffness = 1e3;
    const double r = 1e-3, cut = 0.4e-3;
    Particles p;
    for (int k = 0; k < 600; ++k) {
        const double y = 3e-3 * (k % 30), z = 3e-3 * (k / 30);
        p.add({r - cut, y, z}, r, 2500, Vec3::Zero());
        p.add({0.05, y, z}, r, 2500, Vec3::Zero());
    }
    using Law = ContactLaw<NormalLinear>;
    for (const int threads : {1, 2, 3}) {
        omp_set_num_threads(threads);
        Simulation<Law, false> sim(p, Law(m), {PlaneWall{Vec3::Zero(), Vec3::UnitX()}}, Vec3::Zero(), 1e-7, 0.05 * r);
        sim.stop_governing();
        sim.step();
        const Particles& q = sim.particles();
        std::size_t pushed = 0, untouched = 0, alternations = 0;
        for (std::size_t i = 0; i < q.size(); ++i) {
            const bool at_wall = q.position[i].x() < 2 * r;
            if (at_wall && q.force[i].x() == Approx(1e3 * cut).epsilon(1e-3) && q.force[i].tail<2>().norm() == 0.0) ++pushed;
            if (!at_wall && q.force[i].norm() == 0.0) ++untouched;
            if (i > 0 && at_wall != (q.position[i - 1].x() < 2 * r)) ++alternations;
        }
        CAPTURE(threads);
        REQUIRE(alternations > 1000);  // the marked spheres lie apart in memory, as the case needs
        CHECK(pushed == 600);
        CHECK(untouched == 600);
    }
    omp_set_num_threads(omp_get_num_procs());
}
