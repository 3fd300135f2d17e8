// Neighbour search, conservation laws and the liquid bridge inside the engine.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <omp.h>
#include <random>
#include <sstream>
#include <tuple>
#include <type_traits>
#include <utility>

#include "bridge/mikami.hpp"
#include "bridge/young_laplace.hpp"
#include "dem/simulation.hpp"
#include "slump/shared_engines.hpp"  // the library's copies of the engines it shares

using namespace demscale;
using namespace demscale::dem;

namespace {

// n polydisperse spheres (0.5-1.5 mm) at random, non-overlapping positions in a cube of side L.
Particles random_cloud(int n, double side, unsigned seed, double speed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    Particles p;
    while (static_cast<int>(p.size()) < n) {
        const double r = 0.5e-3 + 1e-3 * u(rng);
        const Vec3 x(side * u(rng), side * u(rng), side * u(rng));
        bool free = true;
        for (std::size_t k = 0; k < p.size() && free; ++k) free = (p.position[k] - x).norm() > p.radius[k] + r;
        if (free) p.add(x, r, 2500, speed * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    }
    return p;
}

}  // namespace

TEST_CASE("Neighbour list equals brute force, also after many rebuilds", "[dem][neighbors]") {
    Particles p = random_cloud(400, 0.03, 7, 0);
    for (std::size_t k = 0; k < p.size(); k += 3) p.fixed[k] = 1;  // fixed spheres: never paired with each other
    NeighborList list(0.2e-3);
    list.build(p);
    CHECK(list.pairs() == brute_force_pairs(p, list.cutoff_gap()));
    CHECK(std::none_of(list.pairs().begin(), list.pairs().end(), [&](auto q) { return p.fixed[q.first] && p.fixed[q.second]; }));
    CHECK(std::any_of(list.pairs().begin(), list.pairs().end(), [&](auto q) { return p.fixed[q.first] != p.fixed[q.second]; }));
    // Random walks: whenever the list says it is still valid, every touching pair is in it.
    std::mt19937 rng(11);
    std::normal_distribution<double> step(0, 0.02e-3);
    int rebuilds = 0;
    std::size_t touching = 0;
    for (int n = 0; n < 300; ++n) {
        for (auto& x : p.position) x += Vec3(step(rng), step(rng), step(rng));
        if (list.needs_rebuild(p)) {
            list.build(p);
            ++rebuilds;
            REQUIRE(list.pairs() == brute_force_pairs(p, list.cutoff_gap()));
        }
        for (const auto& pair : brute_force_pairs(p, 0.0)) {
            REQUIRE(std::binary_search(list.pairs().begin(), list.pairs().end(), pair));
            ++touching;
        }
    }
    CHECK(rebuilds > 5);
    CHECK(touching > 0);  // the walks brought spheres into contact
}

TEST_CASE("Neighbour list: rebuilt once the two spheres that moved most could close the skin", "[dem][neighbors]") {
    // Three spheres in a row, 1 mm radius, gaps of 1.05 skins: none listed. An unlisted pair can
    // touch only after its spheres have moved a skin between them.
    const double r = 1e-3, skin = 0.2e-3, pitch = 2 * r + 1.05 * skin;
    Particles p;
    for (int k = 0; k < 3; ++k) p.add(Vec3(k * pitch, 0, 0), r, 2500);
    NeighborList list(skin);
    list.build(p);
    REQUIRE(list.pairs().empty());
    // One sphere alone moves 0.9 skin towards its neighbour: still valid (the old rule, any sphere
    // past skin/2, rebuilt here), and indeed nothing touches.
    p.position[0].x() += 0.9 * skin;
    CHECK_FALSE(list.needs_rebuild(p));
    CHECK(brute_force_pairs(p, 0.0).empty());
    // Its neighbour comes 0.11 skin towards it: together they could now have closed the gap.
    p.position[1].x() -= 0.11 * skin;
    CHECK(list.needs_rebuild(p));
    // The rule does not ask which spheres moved (it is a bound): the two outer ones moving away,
    // 0.45 skin each, keep the list; 0.56 and 0.45 rebuild it, though no gap closed.
    p.position = {Vec3(0, 0, 0), Vec3(pitch, 0, 0), Vec3(2 * pitch, 0, 0)};
    list.build(p);
    p.position[0].x() -= 0.45 * skin, p.position[2].x() += 0.45 * skin;
    CHECK_FALSE(list.needs_rebuild(p));
    p.position[0].x() -= 0.11 * skin;
    CHECK(list.needs_rebuild(p));
}

TEST_CASE("Free cloud with friction conserves linear and angular momentum", "[dem][conservation]") {
    Material m;
    m.youngs_modulus = 5e6;
    m.restitution = 0.5;
    m.friction = 0.5;
    Particles p = random_cloud(150, 0.012, 3, 0.5);
    Simulation sim(p, ContactLaw<NormalHertz, TangentialMindlin>(m), {}, Vec3::Zero(), 2e-6, 0.2e-3);
    const Vec3 p0 = linear_momentum(sim.particles()), l0 = angular_momentum(sim.particles());
    const double e0 = sim.energy().kinetic;
    double scale_p = 0, scale_l = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        scale_p += p.mass[i] * p.velocity[i].norm();
        scale_l += p.mass[i] * p.velocity[i].norm() * p.position[i].norm();
    }
    for (int n = 0; n < 3000; ++n) sim.step();
    CHECK(sim.energy().kinetic < e0);  // collisions happened and dissipated
    CHECK((linear_momentum(sim.particles()) - p0).norm() < 1e-12 * scale_p);
    CHECK((angular_momentum(sim.particles()) - l0).norm() < 1e-9 * scale_l);
}

TEST_CASE("Elastic frictionless spheres in a box keep their energy over many collisions", "[dem][conservation]") {
    Material m;
    m.youngs_modulus = 5e6;
    m.restitution = 1.0;
    Particles p = random_cloud(60, 0.01, 5, 0.3);
    for (auto& x : p.position) x += Vec3(2e-3, 2e-3, 2e-3);
    std::vector<Wall> box;
    for (int k = 0; k < 3; ++k) {
        box.push_back(PlaneWall{Vec3::Zero(), Vec3::Unit(k)});
        box.push_back(PlaneWall{Vec3::Constant(0.014), -Vec3::Unit(k)});
    }
    Simulation sim(p, ContactLaw<NormalHertz>(m), box, Vec3::Zero(), 1e-6, 0.2e-3);
    const auto total = [&] { const auto e = sim.energy(); return e.kinetic + e.stored.normal; };
    const double e0 = total();
    for (int n = 0; n < 20000; ++n) sim.step();
    CHECK(std::abs(total() - e0) < 1e-4 * e0);
}

TEST_CASE("Liquid bridge in the engine: library force, rupture, no reform until contact", "[dem][bridge]") {
    const double r = 1e-3, gamma = 0.074, vhat = 0.05544;
    Material m;
    const auto k = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}});
    using Wet = ContactLaw<NormalHertz, TangentialNone, CohesionLiquidBridge>;
    Particles p;
    p.add({0, 0, 0}, r, 2200);
    p.add({2 * r, 0, 0}, r, 2200);  // touching: the bridge forms
    Simulation sim(p, Wet(m, CohesionLiquidBridge{k, r, gamma, std::nullopt}), {}, Vec3::Zero(), 1e-6, 0.1 * r);
    // The list reaches only the skin: held at 0.1-0.3 R the bridge lies beyond it, so it is the
    // engine that keeps the bridged pair listed across the rebuilds these moves cause.
    CHECK(sim.neighbors().cutoff_gap() < 0.3 * r);
    auto held_at = [&](double hhat) {
        sim.particles().position[1] = Vec3(2 * r + hhat * r, 0, 0);
        sim.refresh_forces();
        return sim.particles().force[0].x();  // attraction pulls particle 0 towards +x
    };
    for (double hhat : {0.01, 0.1, 0.3}) {
        INFO("hhat = " << hhat);
        CHECK(held_at(hhat) == Approx(M_PI * r * gamma * bridge::mikami_fhat(k, hhat)).epsilon(1e-12));
        CHECK(sim.particles().force[1].x() == Approx(-sim.particles().force[0].x()));
    }
    CHECK(held_at(k.hhat_rupture * 1.001) == 0.0);  // ruptured
    CHECK(held_at(0.1) == 0.0);                     // back within range: no bridge until contact
    held_at(0.0);                                   // contact: forms again
    CHECK(held_at(0.1) == Approx(M_PI * r * gamma * bridge::mikami_fhat(k, 0.1)).epsilon(1e-12));
    // Overlapping (at rest): the bridge pulls with its contact value F̂(0) against Hertz's push,
    // 4/3 E* √(R/2) δ^(3/2) with E* = E / (2(1 − ν²)) (by hand, not the law's own).
    const double e_star = m.youngs_modulus / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
    for (double delta_hat : {1e-4, 1e-3, 1e-2}) {
        INFO("overlap = " << delta_hat << " R");
        const double delta = delta_hat * r, hertz = 4.0 / 3.0 * e_star * std::sqrt(r / 2) * std::pow(delta, 1.5);
        CHECK(held_at(-delta_hat) == Approx(M_PI * r * gamma * bridge::mikami_fhat(k, 0.0) - hertz).epsilon(1e-12));
    }
}

TEST_CASE("Unequal spheres: the bridge takes the harmonic-mean radius 2 R1 R2 / (R1 + R2), by hand, at two radius ratios", "[dem][bridge]") {
    // Willett et al. (2000) scale unequal spheres by R* = 2 R1 R2 / (R1 + R2), in the force and in
    // the rupture gap; the liquid V = V^ R*^3 keeps V^ (docs/models/liquid-bridge.md). By hand:
    // 1 mm with 2 mm gives R* = 4/3 mm; 0.5 mm with 2 mm gives R* = 0.8 mm.
    const double gamma = 0.074;
    const auto k = bridge::mikami_coefficients(0.05544, ContactAngle{Degrees{0}});
    using Wet = ContactLaw<NormalHertz, TangentialNone, CohesionLiquidBridgePerPair>;
    for (const auto& [r1, r2, rh] : {std::tuple{1e-3, 2e-3, 4.0 / 3.0 * 1e-3}, std::tuple{0.5e-3, 2e-3, 0.8e-3}}) {
        INFO("R1 = " << r1 << ", R2 = " << r2);
        Particles p;
        p.add({0, 0, 0}, r1, 2200);
        p.add({r1 + r2, 0, 0}, r2, 2200);  // touching: the bridge forms
        Simulation sim(p, Wet(Material{}, CohesionLiquidBridgePerPair{k, r2, gamma, std::nullopt}), {}, Vec3::Zero(), 1e-6, 0.1 * r1);
        for (double hhat : {0.0, 0.05, 0.2}) {
            INFO("gap / R* = " << hhat);
            sim.particles().position[1] = Vec3(r1 + r2 + hhat * rh, 0, 0);
            sim.refresh_forces();
            // Eq. 1 with R*: F = pi R* gamma F^(gap / R*).
            CHECK(sim.particles().force[0].x() == Approx(M_PI * rh * gamma * bridge::mikami_fhat(k, hhat)).epsilon(1e-12));
        }
        sim.particles().position[1] = Vec3(r1 + r2 + 0.999 * k.hhat_rupture * rh, 0, 0);  // just inside rupture in R*
        sim.refresh_forces();
        CHECK(sim.particles().force[0].x() > 0.0);
        sim.particles().position[1] = Vec3(r1 + r2 + 1.001 * k.hhat_rupture * rh, 0, 0);  // beyond rupture in R*, within it in R2
        sim.refresh_forces();
        CHECK(sim.particles().force[0].x() == 0.0);
    }
}

TEST_CASE("Exact (tabulated) bridges in the engine: the Young-Laplace force between spheres and to a floor, rupture at the exact gap",
          "[dem][bridge][curve]") {
    const double r = 1e-3, gamma = 0.074, vhat = 0.05544;
    const ContactAngle theta{Degrees{20}};
    const auto pair_curve = bridge::BridgeCurve::exact(vhat, theta, bridge::BridgeGeometry::sphere_sphere);
    const auto wall_curve = bridge::BridgeCurve::exact(vhat, theta, bridge::BridgeGeometry::sphere_wall);
    const bridge::YoungLaplaceBridge spheres(vhat, theta);
    const auto plate = bridge::YoungLaplaceBridge::sphere_plane(vhat, theta, theta);
    using Wet = ContactLaw<NormalHertz, TangentialNone, CohesionLiquidBridge>;
    Particles p;
    p.add({0, 0, r}, r, 2200);
    p.add({2 * r, 0, r}, r, 2200);  // touching each other and the floor: both bridges form
    const std::vector<Wall> floor{PlaneWall{Vec3::Zero(), Vec3::UnitZ()}};
    Simulation sim(p, Wet(Material{}, CohesionLiquidBridge{pair_curve, r, gamma, wall_curve}), floor, Vec3::Zero(), 1e-6, 0.1 * r);
    auto exact_force = [&](const bridge::YoungLaplaceBridge& b, double hhat) {
        const auto s = b.solve(hhat);
        REQUIRE(s.ok());
        return 2 * M_PI * r * gamma * s.shape.fhat_neck;  // F/(2πRγ) of the solver, N
    };
    for (double x : {0.05, 0.5, 0.95}) {
        INFO("gap / rupture gap = " << x);
        // Sphere 0 above the floor at a gap, sphere 1 at a gap from sphere 0 and far above the floor.
        const double floor_gap = x * plate.hhat_rupture(), pair_gap = x * spheres.hhat_rupture();
        sim.particles().position[0] = Vec3(0, 0, r + floor_gap * r);
        sim.particles().position[1] = sim.particles().position[0] + (2 + pair_gap) * r * Vec3(1, 0, 0.6).normalized();
        sim.refresh_forces();
        const Vec3 along = Vec3(1, 0, 0.6).normalized();
        const Vec3 on_1 = sim.particles().force[1];
        CHECK(-on_1.dot(along) == Approx(exact_force(spheres, pair_gap)).epsilon(5e-4));
        const Vec3 on_0 = sim.particles().force[0] + on_1;  // the floor's pull alone (the pair's cancels)
        CHECK(-on_0.z() == Approx(exact_force(plate, floor_gap)).epsilon(5e-4));
    }
    sim.particles().position[0] = Vec3(0, 0, r + 1.001 * plate.hhat_rupture() * r);
    sim.particles().position[1] = sim.particles().position[0] + (2 + 1.001 * spheres.hhat_rupture()) * r * Vec3(1, 0, 0.6).normalized();
    sim.refresh_forces();
    CHECK(sim.particles().force[0].norm() == 0.0);  // both ruptured
    CHECK(sim.particles().force[1].norm() == 0.0);
}

TEST_CASE("Viscous bridge: the lubrication force 6 pi mu R*^2 v_n / s by hand, across a gap and at contact, booked as lost",
          "[dem][bridge][viscous]") {
    const double r = 1e-3, gamma = 0.074, mu = 1e-3, s_min = 0.01 * r, v = 0.01;
    const auto k = bridge::mikami_coefficients(0.05544, ContactAngle{Degrees{0}});
    const CohesionLiquidBridge still{k, r, gamma, std::nullopt}, viscous{k, r, gamma, std::nullopt, mu, s_min};
    const double rstar = r / 2;  // equal spheres
    SECTION("the law at a fixed gap and speed, and its loss") {
        CohesionLiquidBridge::State a, b;
        Dissipation la, lb;
        still.pull(0.0, r, 0.0, 1e-6, false, a, la), viscous.pull(0.0, r, 0.0, 1e-6, false, b, lb);  // contact: bridges form
        for (double gap_hat : {0.0, 0.001, 0.05, 0.2}) {
            const double gap = gap_hat * r, s = std::max(gap, s_min), dt = 1e-6;
            INFO("gap " << gap_hat << " R");
            const double f_still = still.pull(-gap, r, v, dt, false, a, la);
            Dissipation step;  // this step's loss alone
            const double f = viscous.pull(-gap, r, v, dt, false, b, step);
            const double lubrication = 6 * M_PI * mu * rstar * rstar * v / s;  // Pitois et al. (2000), s << R
            CHECK(f - f_still == Approx(lubrication).epsilon(1e-12));
            CHECK(step.bridge == Approx(lubrication * v * dt).epsilon(1e-12));
            CHECK(viscous.pull(-gap, r, -v, dt, false, b, lb) - f_still == Approx(-lubrication).epsilon(1e-12));  // approaching: pushes
        }
        // Beyond rupture nothing acts, viscous or not.
        CHECK(viscous.pull(-1.01 * k.hhat_rupture * r, r, v, 1e-6, false, b, lb) == 0.0);
        CHECK(viscous.pull(-0.1 * r, r, v, 1e-6, false, b, lb) == 0.0);  // no bridge until contact again
    }
    SECTION("in the engine: a bridged pair separating across a gap feels capillary plus lubrication") {
        using Wet = ContactLaw<NormalHertz, TangentialNone, CohesionLiquidBridge>;
        Particles p;
        p.add({0, 0, 0}, r, 2200);
        p.add({2 * r, 0, 0}, r, 2200);  // touching: the bridge forms
        Simulation sim(p, Wet(Material{}, viscous), {}, Vec3::Zero(), 1e-6, 0.1 * r);
        sim.particles().position[1] = Vec3(2.1 * r, 0, 0);
        sim.particles().velocity[1] = Vec3(v, 0, 0);  // separating at v
        sim.refresh_forces();
        const double capillary = M_PI * r * gamma * bridge::mikami_fhat(k, 0.1);
        CHECK(sim.particles().force[0].x() == Approx(capillary + 6 * M_PI * mu * rstar * rstar * v / (0.1 * r)).epsilon(1e-12));
        CHECK(sim.particles().force[1].x() == Approx(-sim.particles().force[0].x()));
    }
}

// The finite-volume lubrication by a second method: the Reynolds film between a sphere of R* and a
// plane, gap h(ρ) = s + ρ²/(2R*), squeezed at v and wetted out to the meniscus ρ_m where the
// liquid's volume ∫ 2πρ h dρ reaches V; p(ρ_m) = 0, dp/dρ = −6 μ v ρ / h³, F = ∫ 2πρ p dρ. Here
// integrated by the midpoint rule (F = ∫ π ρ² (−dp/dρ) dρ after one integration by parts).
double reynolds_film_force(double mu, double rstar, double s, double v, double volume) {
    // ρ_m from V = π ρ_m² s + π ρ_m⁴ / (4 R*), by bisection.
    double lo = 0, hi = 10 * rstar;
    for (int i = 0; i < 200; ++i) {
        const double m = 0.5 * (lo + hi);
        (M_PI * m * m * s + M_PI * m * m * m * m / (4 * rstar) < volume ? lo : hi) = m;
    }
    const int n = 200000;
    const double d = lo / n;
    double f = 0;
    for (int i = 0; i < n; ++i) {
        const double rho = (i + 0.5) * d, h = s + rho * rho / (2 * rstar);
        f += M_PI * rho * rho * 6 * mu * v * rho / (h * h * h) * d;
    }
    return f;
}

TEST_CASE("Viscous bridge: the finite-volume lubrication (Pitois et al. 2000) against the Reynolds film wetted by V",
          "[dem][bridge][viscous]") {
    const double r = 1e-3, gamma = 0.074, mu = 1e-3, s_min = 0.01 * r, v = 0.01, dt = 1e-6, vhat = 0.055;
    const auto k = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}});
    const auto plate = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}}, {}, bridge::BridgeGeometry::sphere_wall);
    const CohesionLiquidBridge still{k, r, gamma, plate},
        unbounded{k, r, gamma, plate, mu, s_min},
        finite{k, r, gamma, plate, mu, s_min, Lubrication::finite_volume, vhat};
    for (const bool wall : {false, true}) {
        const double rstar = wall ? r : r / 2;
        CohesionLiquidBridge::State a, b, c;
        Dissipation lost;
        still.pull(0.0, r, 0.0, dt, wall, a, lost), unbounded.pull(0.0, r, 0.0, dt, wall, b, lost), finite.pull(0.0, r, 0.0, dt, wall, c, lost);
        for (double gap_hat : {0.0, 0.02, 0.1, 0.3}) {
            INFO((wall ? "wall" : "spheres") << ", gap " << gap_hat << " R");
            const double s = std::max(gap_hat * r, s_min);
            const double f0 = still.pull(-gap_hat * r, r, v, dt, wall, a, lost);
            Dissipation step;
            const double fv = finite.pull(-gap_hat * r, r, v, dt, wall, c, step) - f0;
            const double film = reynolds_film_force(mu, rstar, s, v, vhat * r * r * r);
            CHECK(fv == Approx(film).epsilon(1e-6));
            CHECK(step.bridge == Approx(fv * v * dt).epsilon(1e-9));  // fv: a difference of forces
            CHECK(fv < unbounded.pull(-gap_hat * r, r, v, dt, wall, b, lost) - f0);  // never above the unbounded force
        }
    }
    // At V^ = 0.055 between spheres the unbounded force is 3.58 x the finite one at s = 0.1 R (by
    // hand: 1 / (1 - 1/sqrt(1 + 2 V^ / (pi 0.01)))^2), and 79 x at 0.36 R, near rupture (0.369 R).
    REQUIRE(k.hhat_rupture > 0.36);
    REQUIRE(plate.hhat_rupture > 0.3);
    CohesionLiquidBridge::State b, c;
    Dissipation lost;
    unbounded.pull(0.0, r, 0.0, dt, false, b, lost), finite.pull(0.0, r, 0.0, dt, false, c, lost);
    auto ratio = [&](double gap_hat) {
        const double f0 = still.pull(-gap_hat * r, r, 0.0, dt, false, b, lost);
        return (unbounded.pull(-gap_hat * r, r, v, dt, false, b, lost) - f0) / (finite.pull(-gap_hat * r, r, v, dt, false, c, lost) - f0);
    };
    CHECK(ratio(0.1) == Approx(3.58).epsilon(2e-3));
    CHECK(ratio(0.36) == Approx(78.73).epsilon(2e-3));
}

TEST_CASE("Viscous bridge: the sliding drag 6 pi mu R* (8/15 ln(R*/s) + 0.9588) v_t by hand, with its torques",
          "[dem][bridge][viscous]") {
    const double r = 1e-3, gamma = 0.074, mu = 1e-3, s_min = 0.01 * r, v = 0.01, dt = 1e-6;
    const auto k = bridge::mikami_coefficients(0.05544, ContactAngle{Degrees{0}});
    const CohesionLiquidBridge still{k, r, gamma, std::nullopt}, viscous{k, r, gamma, std::nullopt, mu, s_min};
    const double rstar = r / 2;
    // Goldman, Cox & Brenner (1967): a sphere sliding parallel to a plane at gap s << R.
    auto by_hand = [&](double gap) {
        return 6 * M_PI * mu * rstar * (8.0 / 15.0 * std::log(rstar / std::max(gap, s_min)) + 0.9588);
    };
    SECTION("the law at a fixed gap and sliding speed, and its loss") {
        CohesionLiquidBridge::State b, none;
        Dissipation lost;
        viscous.pull(0.0, r, 0.0, dt, false, b, lost);  // contact: the bridge forms
        const Vec3 sliding(0, v, 0.5 * v);
        for (double gap_hat : {0.0, 0.001, 0.05, 0.2}) {
            INFO("gap " << gap_hat << " R");
            Dissipation step;
            const Vec3 f = viscous.drag(-gap_hat * r, r, sliding, dt, false, b, step);
            CHECK((f + by_hand(gap_hat * r) * sliding).norm() < 1e-12 * f.norm());
            CHECK(step.bridge == Approx(by_hand(gap_hat * r) * sliding.squaredNorm() * dt).epsilon(1e-12));
        }
        CHECK(by_hand(0.0) == Approx(6 * M_PI * mu * rstar * (8.0 / 15.0 * std::log(50.0) + 0.9588)));  // s = s_min = R*/50
        CHECK(viscous.drag(-0.05 * r, r, sliding, dt, false, none, lost) == Vec3::Zero());   // no bridge: no drag
        CHECK(still.drag(-0.05 * r, r, sliding, dt, false, b, lost) == Vec3::Zero());        // no viscosity: no drag
    }
    SECTION("in the engine: a bridged pair sliding and spinning across a gap") {
        using Wet = ContactLaw<NormalHertz, TangentialNone, CohesionLiquidBridge>;
        Particles p;
        p.add({0, 0, 0}, r, 2200);
        p.add({2 * r, 0, 0}, r, 2200);  // touching: the bridge forms
        Simulation sim(p, Wet(Material{}, viscous), {}, Vec3::Zero(), dt, 0.1 * r);
        const double spin = 3.0;  // rad/s about z
        sim.particles().position[1] = Vec3(2.1 * r, 0, 0);
        sim.particles().velocity[1] = Vec3(0, v, 0);
        sim.particles().angular_velocity[1] = Vec3(0, 0, spin);
        sim.refresh_forces();
        // The gap's middle lies 1.05 R from each centre. There sphere 1 moves at v + ω × (−1.05 R x̂)
        // = (v − 1.05 R ω) ŷ, so sphere 0 is dragged along +ŷ by c (v − 1.05 R ω), and both are
        // turned about +ẑ by the lever 1.05 R.
        const double drag = by_hand(0.1 * r) * (v - 1.05 * r * spin);
        const auto& q = sim.particles();
        CHECK(q.force[0].x() == Approx(M_PI * r * gamma * bridge::mikami_fhat(k, 0.1)).epsilon(1e-12));  // v_n = 0
        CHECK(q.force[0].y() == Approx(drag).epsilon(1e-12));
        CHECK(q.force[1].y() == Approx(-drag).epsilon(1e-12));
        CHECK(q.torque[0].z() == Approx(1.05 * r * drag).epsilon(1e-12));
        CHECK(q.torque[1].z() == Approx(1.05 * r * drag).epsilon(1e-12));
        CHECK(std::abs(q.torque[0].x()) + std::abs(q.torque[0].y()) < 1e-12 * std::abs(q.torque[0].z()));
    }
}

TEST_CASE("A bridge stretched far beyond the list's reach pulls until it ruptures", "[dem][bridge][neighbors]") {
    const double r = 1e-3, gamma = 0.074, vhat = 0.05544, skin = 0.01 * r;
    const auto k = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}});
    using Wet = ContactLaw<NormalHertz, TangentialNone, CohesionLiquidBridge>;
    Particles p;
    p.add({0, 0, 0}, r, 2200, {-0.5, 0, 0});  // touching (the bridge forms), flying apart fast
    p.add({2 * r, 0, 0}, r, 2200, {0.5, 0, 0}); // enough to escape the bridge's pull
    Simulation sim(p, Wet(Material{}, CohesionLiquidBridge{k, r, gamma, std::nullopt}), {}, Vec3::Zero(), 1e-6, skin);
    int stretched = 0, ruptured = 0;
    const std::size_t builds0 = sim.neighbors().builds();
    while (ruptured < 50) {
        sim.step();
        const auto& q = sim.particles();
        const double hhat = ((q.position[1] - q.position[0]).norm() - 2 * r) / r;
        REQUIRE(hhat > 0);
        const double expected = hhat <= k.hhat_rupture ? M_PI * r * gamma * bridge::mikami_fhat(k, hhat) : 0.0;
        INFO("step " << sim.steps() << ", gap " << hhat << " R");
        REQUIRE(q.force[0].x() == Approx(expected).epsilon(1e-12));  // pulls 0 towards +x
        hhat <= k.hhat_rupture ? ++stretched : ++ruptured;
    }
    CHECK(stretched > 100);
    CHECK(sim.neighbors().builds() - builds0 > 20);  // rebuilt again and again while the bridge held
}

TEST_CASE("A wet scene's results do not depend on the neighbour skin, to the bit", "[dem][bridge][neighbors]") {
    // The skin only decides how often the list is rebuilt and how many idle pairs it carries; the
    // acting pairs and their order are the same, so trajectories must agree exactly. A skin of
    // 1.5 R reaches far past the rupture gap (0.38 R) with every pair that could ever act listed.
    const double r = 1e-3;
    const auto k = bridge::mikami_coefficients(0.05544, ContactAngle{Degrees{0}});
    Material m;
    m.friction = 0.5;
    m.rolling_friction = 0.1;
    using Wet = ContactLaw<NormalHertz, TangentialMindlin, CohesionLiquidBridge, RollingEpsd>;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    Particles p;
    for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 5; ++b)
            for (int c = 0; c < 5; ++c) p.add(2.05 * r * Vec3(a, b, c), r, 2200, Vec3(u(rng), u(rng), u(rng)));
    // Also when the engine reorders its spheres in space every 150 steps (the pair order follows
    // the spheres' order): the reorders fall on the same steps whatever the skin.
    const SpatialSort sorts[] = {SpatialSort{}, SpatialSort{0, 150}};
    for (const SpatialSort& sort : sorts) {
        auto run = [&](double skin) {
            Simulation sim(p, Wet(m, CohesionLiquidBridge{k, r, 0.074, std::nullopt}), {}, Vec3::Zero(), 2e-6, skin, sort);
            double most_bridge_energy = 0;
            for (int n = 0; n < 4000; ++n) {
                sim.step();
                if (n % 200 == 0) most_bridge_energy = std::min(most_bridge_energy, sim.energy().stored.bridge);
            }
            return std::tuple(sim.in_input_order(), sim.neighbors().builds(), most_bridge_energy, sim.spatial_sorts());
        };
        const auto [tight, tight_builds, tight_bridges, tight_sorts] = run(0.02 * r);
        const auto [wide, wide_builds, wide_bridges, wide_sorts] = run(1.5 * r);
        CHECK(tight_sorts == (sort.min_particles == 0 ? 27 : 0));  // at step 0, 150, … 3900
        CHECK(wide_sorts == tight_sorts);
        CHECK(tight_builds > (sort.min_particles == 0 ? 5 : 10) * wide_builds);  // a reorder forces a build
        CHECK(tight_bridges < 0);  // bridges formed
        CHECK(tight_bridges == wide_bridges);
        CHECK(tight.position == wide.position);
        CHECK(tight.velocity == wide.velocity);
        CHECK(tight.angular_velocity == wide.angular_velocity);
    }
}

TEST_CASE("Bad scenes stop with the particle and the step", "[dem][errors]") {
    Material m;
    Particles p;
    p.add({0, 0, 1e-3}, 1e-3, 2500, {0, 0, -50});
    Simulation sim(p, ContactLaw<NormalHertz>(m), {PlaneWall{}}, Vec3::Zero(), 1e-5, 1e-4);
    CHECK_THROWS_WITH([&] { for (int n = 0; n < 100; ++n) sim.step(); }(), Catch::Matchers::Contains("particle 0 left the domain"));
    CHECK_THROWS_WITH(Particles().add({0, 0, 0}, -1e-3, 2500), Catch::Matchers::Contains("particle radius = -0.001"));
    CHECK_THROWS_AS(Particles().add({NAN, 0, 0}, 1e-3, 2500), InputError);
}

TEST_CASE("A NaN stops the run within the step, naming the particle, the step and the contact", "[dem][errors]") {
    Material m;
    m.friction = 0.5;
    using Law = ContactLaw<NormalHertz, TangentialMindlin>;
    // Two centres that coincide: the contact normal is 0/0, so the first force is NaN.
    Particles p;
    p.add({0, 0, 5e-3}, 1e-3, 2500);
    p.add({3e-3, 0, 5e-3}, 1e-3, 2500);
    p.add({3e-3, 0, 5e-3}, 1e-3, 2500);
    CHECK_THROWS_WITH((Simulation(p, Law(m), {PlaneWall{}}, Vec3::Zero(), 1e-5, 1e-4)),
                      Catch::Matchers::Contains("non-finite force on particle 1 at step 0") &&
                          Catch::Matchers::Contains("from its contact with particle 2 (gap -0.002"));
    // A velocity that became NaN (e.g. set by hand): caught in the next step, with the cause.
    Particles q;
    q.add({0, 0, 5e-3}, 1e-3, 2500);
    q.add({3e-3, 0, 5e-3}, 1e-3, 2500);
    Simulation sim(q, Law(m), {PlaneWall{}}, Vec3::Zero(), 1e-5, 1e-4);
    for (int n = 0; n < 10; ++n) sim.step();
    sim.particles().velocity[1] = Vec3(NAN, 0, 0);
    CHECK_THROWS_WITH(sim.step(), Catch::Matchers::Contains("non-finite position of particle 1 at step 10") &&
                                      Catch::Matchers::Contains("its velocity is not finite"));
}

TEST_CASE("Restart from a checkpoint continues bit for bit", "[dem][restart]") {
    Material m;
    m.youngs_modulus = 5e6;
    m.friction = 0.5;
    m.rolling_friction = 0.1;
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, RollingEpsd>;
    Particles p = random_cloud(120, 0.01, 9, 0.3);
    for (std::size_t k = 0; k < p.size(); k += 10) p.fixed[k] = 1, p.velocity[k].setZero();  // held in place, also after the restart
    const std::vector<Wall> walls{PlaneWall{Vec3(0, 0, -0.002), Vec3::UnitZ()}};
    Simulation straight(p, Law(m), walls, Vec3(0, 0, -9.81), 2e-6, 0.2e-3);
    for (int n = 0; n < 4000; ++n) straight.step();

    Simulation first(p, Law(m), walls, Vec3(0, 0, -9.81), 2e-6, 0.2e-3);
    for (int n = 0; n < 1700; ++n) first.step();
    std::stringstream checkpoint;
    first.save(checkpoint);
    Simulation resumed(Particles{}, Law(m), walls, Vec3(0, 0, -9.81), 2e-6, 0.2e-3);
    resumed.load(checkpoint);
    for (int n = 0; n < 2300; ++n) resumed.step();

    REQUIRE(resumed.steps() == straight.steps());
    const auto& a = straight.particles();
    const auto& b = resumed.particles();
    CHECK(std::memcmp(a.position.data(), b.position.data(), a.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(a.angular_velocity.data(), b.angular_velocity.data(), a.size() * sizeof(Vec3)) == 0);
    CHECK(resumed.neighbors().builds() == straight.neighbors().builds());
    for (std::size_t k = 0; k < p.size(); k += 10) CHECK(b.position[k] == p.position[k]);
    std::stringstream garbage("not a checkpoint at all, just text");
    CHECK_THROWS_WITH(resumed.load(garbage), Catch::Matchers::Contains("not a demscale checkpoint"));

    // Without the ledger the histories are shorter: the same restart, and a checkpoint of the
    // other kind is refused rather than misread.
    Simulation<Law, false> quiet(p, Law(m), walls, Vec3(0, 0, -9.81), 2e-6, 0.2e-3);
    Simulation<Law, false> quiet_resumed(Particles{}, Law(m), walls, Vec3(0, 0, -9.81), 2e-6, 0.2e-3);
    for (int n = 0; n < 1700; ++n) quiet.step();
    std::stringstream quiet_checkpoint;
    quiet.save(quiet_checkpoint);
    quiet_resumed.load(quiet_checkpoint);
    for (int n = 0; n < 2300; ++n) quiet_resumed.step();
    CHECK(std::memcmp(a.position.data(), quiet_resumed.particles().position.data(), a.size() * sizeof(Vec3)) == 0);
    std::stringstream booked_checkpoint;
    first.save(booked_checkpoint);
    CHECK_THROWS_WITH(quiet_resumed.load(booked_checkpoint), Catch::Matchers::Contains("written with the energy ledger on"));
}

TEST_CASE("Results do not depend on the number of threads", "[dem][threads]") {
    Material m;
    m.friction = 0.5;
    // Large enough that every loop runs in parallel (more than 512 particles and listed pairs).
    Particles p = random_cloud(600, 0.02, 3, 0.5);
    auto run = [&](int threads) {
        omp_set_num_threads(threads);
        Simulation sim(p, ContactLaw<NormalHertz, TangentialMindlin>(m), {}, Vec3::Zero(), 2e-6, 0.5e-3);
        REQUIRE(sim.neighbors().pairs().size() > 512);
        for (int n = 0; n < 500; ++n) sim.step();
        return sim.particles().position;
    };
    const auto one = run(1), two = run(2), three = run(3);  // three: rebuilds and shares in odd runs
    omp_set_num_threads(omp_get_num_procs());
    CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(one.data(), three.data(), one.size() * sizeof(Vec3)) == 0);
}

TEST_CASE("Results do not depend on the thread count changing between steps, wet, with walls", "[dem][threads]") {
    // The thread governor switches between one thread and all of them between steps; the work
    // stays cut into the shares of the threads the run was given. On two shares the spheres on a
    // slab's face gather their pairs' results from a buffer, on one share every result is added at
    // once: a pair that stopped acting while one thread ran both shares must not bring back a stale
    // result. Bridges (central pulls across a gap) form, stretch and rupture here.
    Material m;
    m.friction = 0.5;
    Particles p = random_cloud(700, 0.02, 17, 0.5);
    for (auto& v : p.velocity) v.z() -= 1.0;
    // A tube around the cloud, sliding sideways and up through the whole run: its work on the
    // spheres is booked per share too.
    const FrustumWall tube{Vec3(0.01, 0.01, -1.6e-3), 0.016, 0.016, 0.03, Vec3(1.5, 0, 0.5), 0, 1};
    const std::vector<Wall> walls{PlaneWall{Vec3(0, 0, -1.6e-3), Vec3::UnitZ()}, tube};
    using Wet = ContactLaw<NormalHertz, TangentialMindlin, CohesionLiquidBridge, RollingEpsd>;
    const auto k = bridge::mikami_coefficients(0.05, ContactAngle{Degrees{20}});
    const Wet law(m, CohesionLiquidBridge{k, 1e-3, 0.074, std::nullopt});
    auto run = [&](auto ledger, int given, bool switching) {
        omp_set_num_threads(given);
        Simulation<Wet, decltype(ledger)::value> sim(p, law, walls, Vec3(0, 0, -9.81), 2e-6, 0.5e-3);
        sim.stop_governing();  // the count set below holds for each step
        for (int n = 0; n < 1500; ++n) {
            omp_set_num_threads(switching && (n / 37) % 2 == 0 ? 1 : given);
            sim.step();
        }
        return std::pair(sim.particles(), sim.energy());
    };
    using Off = std::false_type;
    const Particles one = run(Off{}, 1, false).first, switching = run(Off{}, 2, true).first;
    omp_set_num_threads(omp_get_num_procs());
    CHECK(std::memcmp(one.position.data(), switching.position.data(), one.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(one.angular_velocity.data(), switching.angular_velocity.data(), one.size() * sizeof(Vec3)) == 0);

    // The energy ledger sums per share, in share order: the same bits whichever threads ran the
    // shares (a sum per thread would add both shares' losses into one on the one-thread steps).
    using On = std::true_type;
    const auto [steady, booked] = run(On{}, 2, false);
    const auto [switched, booked_switching] = run(On{}, 2, true);
    omp_set_num_threads(omp_get_num_procs());
    REQUIRE(booked.dissipated.total() > 0);
    REQUIRE(booked.wall_work != 0);
    CHECK(std::memcmp(steady.position.data(), one.position.data(), one.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(steady.position.data(), switched.position.data(), one.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(&booked.dissipated, &booked_switching.dissipated, sizeof(booked.dissipated)) == 0);
    CHECK(std::memcmp(&booked.wall_work, &booked_switching.wall_work, sizeof(double)) == 0);
}

TEST_CASE("Results do not depend on the number of threads, with walls and without the ledger", "[dem][threads]") {
    // Without the ledger each thread takes a slab of space, cut by the work of the pairs that
    // acted when the list was drawn, so a pair's thread and whether its spheres gather change as
    // the spheres fall; the wall loop is threaded too. A particle's forces must not change with either.
    Material m;
    m.friction = 0.5;
    Particles p = random_cloud(700, 0.02, 11, 0.5);
    for (auto& v : p.velocity) v.z() -= 1.0;  // onto the floor
    const std::vector<Wall> walls{PlaneWall{Vec3(0, 0, -1.6e-3), Vec3::UnitZ()}, PlaneWall{Vec3(-1.6e-3, 0, 0), Vec3::UnitX()}};
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, RollingEpsd>;
    auto run = [&](int threads) {
        omp_set_num_threads(threads);
        Simulation<Law, false> sim(p, Law(m), walls, Vec3(0, 0, -9.81), 2e-6, 0.5e-3);
        for (int n = 0; n < 1000; ++n) sim.step();
        return sim.particles();
    };
    const Particles one = run(1), two = run(2), three = run(3);
    omp_set_num_threads(omp_get_num_procs());
    std::size_t bounced = 0;  // the floor acted: spheres that were falling at 0.5-1.5 m/s no longer are
    for (const auto& v : one.velocity) bounced += v.z() > -0.3;
    CHECK(bounced > 20);
    for (const Particles* q : {&two, &three}) {
        CHECK(std::memcmp(one.position.data(), q->position.data(), one.size() * sizeof(Vec3)) == 0);
        CHECK(std::memcmp(one.angular_velocity.data(), q->angular_velocity.data(), one.size() * sizeof(Vec3)) == 0);
    }
}

TEST_CASE("Every touching pair acts: the engine's forces on a packed cluster are Hertz's summed over all pairs by brute force",
          "[dem][contact]") {
    // A jittered cubic lattice 1.9 radii apart: each sphere presses on its nearest neighbours and
    // lies near the others, so the pair loop's blocks hold both kinds, many blocks over. At rest
    // with fresh histories only the elastic Hertz force acts: 4/3 E* √R* δ^(3/2) along the line of
    // centres, E* = E / (2 (1 − ν²)), summed here over all pairs (no neighbour list).
    Material m;
    m.youngs_modulus = 5e6;
    m.poisson_ratio = 0.3;
    m.friction = 0.5;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(-0.04e-3, 0.04e-3);
    const double r = 1e-3, spacing = 1.9e-3;
    Particles p;
    for (int x = 0; x < 8; ++x)
        for (int y = 0; y < 8; ++y)
            for (int z = 0; z < 6; ++z)
                p.add(Vec3(x * spacing + jitter(rng), y * spacing + jitter(rng), z * spacing + jitter(rng)), r, 2500);
    const Simulation sim(p, ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, RollingEpsd>(m), {}, Vec3::Zero(), 1e-7, 0.3e-3);
    const Particles got = sim.in_input_order();
    const double e_star = m.youngs_modulus / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
    std::size_t touching = 0;
    double largest = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        Vec3 expected = Vec3::Zero();
        for (std::size_t j = 0; j < p.size(); ++j) {
            const Vec3 d = p.position[i] - p.position[j];
            const double overlap = p.radius[i] + p.radius[j] - d.norm();
            if (j == i || overlap <= 0) continue;
            const double r_eff = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
            expected += 4.0 / 3.0 * e_star * std::sqrt(r_eff) * std::pow(overlap, 1.5) * d.normalized();
            touching += i < j;
        }
        largest = std::max(largest, expected.norm());
        INFO("sphere " << i);
        CHECK((got.force[i] - expected).norm() <= 1e-12 * largest + 1e-9 * expected.norm());
        CHECK(got.torque[i].norm() <= 1e-12 * largest);
    }
    CHECK(touching > 600);  // many blocks of 32 listed pairs, each with touching ones
    CHECK(largest > 0);
}

TEST_CASE("The engine's memory by consumer covers, at least, what its spheres and listed pairs hold by hand", "[dem][memory]") {
    // By hand: a sphere holds 5 vectors of 3 doubles, 3 doubles, an int and a byte (149 B) and its
    // two half-step kicks (16 B); a listed pair its (i, j) (8 B), shape (5 doubles) and result (9 doubles).
    const Material m;
    Particles p;
    for (int x = 0; x < 10; ++x)
        for (int y = 0; y < 10; ++y) p.add(Vec3(x * 1.98e-3, y * 1.98e-3, 0), 1e-3, 2500);
    const Simulation sim(p, ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, RollingEpsd>(m), {}, Vec3::Zero(), 1e-7, 0.3e-3);
    const std::size_t pairs = sim.neighbors().pairs().size();
    REQUIRE(pairs >= 180);  // the square lattice's 2 × 10 × 9 touching pairs, at least
    std::map<std::string, std::size_t> by;
    for (const auto& item : sim.memory()) by[item.name] = item.bytes;
    auto named = [&](const std::string& start) {
        const auto it = std::find_if(by.begin(), by.end(), [&](const auto& kv) { return kv.first.rfind(start, 0) == 0; });
        REQUIRE(it != by.end());
        return it->second;
    };
    CHECK(named("spheres") >= 100 * (149 + 16));
    CHECK(named("pair list") >= pairs * 8);
    CHECK(named("pair shapes") >= pairs * 40);
    CHECK(named("pair results") >= pairs * 72);
    CHECK(named("neighbour list") >= pairs * 8 + 100 * 24);
}
