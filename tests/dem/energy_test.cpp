// The energy ledger against independent sources: rigid-body mechanics for what friction and
// rolling resistance dissipate, and the conservation law (kinetic + potential + stored +
// dissipated − wall work = const) on a dry and a wet column collapsing out of a lifted cone.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "bridge/mikami.hpp"
#include "dem/laws/adhesion_sjkr.hpp"
#include "dem/simulation.hpp"
#include "slump/shared_engines.hpp"  // the library's copies of the engines it shares

using namespace demscale;
using namespace demscale::dem;

namespace {
constexpr double r = 1e-3, rho = 2200, g = 9.81;

Material material(double mu, double mu_r) {
    Material m;
    m.density = rho;
    m.youngs_modulus = 5e6;
    m.restitution = 0.5;
    m.friction = mu;
    m.rolling_friction = mu_r;
    return m;
}

// Spheres of radius r on a jittered square lattice inside a cylinder of radius 6.5 r, in layers
// from just above the floor: n of them, not touching.
Particles column(int n) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> jitter(-0.04 * r, 0.04 * r);
    Particles p;
    const double pitch = 2.1 * r;
    for (int layer = 0; static_cast<int>(p.size()) < n; ++layer)
        for (int a = -3; a <= 3; ++a)
            for (int b = -3; b <= 3; ++b) {
                const double x = a * pitch, y = b * pitch;
                if (std::hypot(x, y) > 5.3 * r || static_cast<int>(p.size()) >= n) continue;
                p.add({x + jitter(rng), y + jitter(rng), 1.05 * r + layer * pitch}, r, rho);
            }
    return p;
}

// Drops the column inside a cylinder, lifts the cylinder at 0.3 m/s, removes it, lets the pile
// spread; returns the largest |balance − initial| seen, relative to what was dissipated by then.
template <class Law>
double ledger_drift(const Law& law, double dt, Energy& end) {
    FrustumWall tube;
    tube.bottom_radius = tube.top_radius = 6.5 * r;
    tube.height = 40 * r;
    tube.velocity = Vec3(0, 0, 0.3);
    tube.move_start = 0.08, tube.move_end = 0.08 + 0.03 / 0.3;
    Simulation sim(column(250), law, {PlaneWall{}, tube}, Vec3(0, 0, -g), dt, 0.2 * r);
    const double e0 = sim.energy().balance();
    double drift = 0;
    const int steps = static_cast<int>(std::lround(0.3 / dt)), removal = static_cast<int>(std::lround(0.2 / dt));
    for (int n = 1; n <= steps; ++n) {
        sim.step();
        if (n == removal) sim.remove_wall(1);
        if (n % (steps / 60) == 0) {
            const Energy e = sim.energy();
            drift = std::max(drift, std::abs(e.balance() - e0) / e.dissipated.total());
        }
    }
    end = sim.energy();
    return drift;
}
}  // namespace

TEST_CASE("Friction dissipates m v0^2 / 7 while a thrown sphere goes from sliding to rolling", "[dem][energy]") {
    // From 5/7 v0 at the end of slipping (rigid-body mechanics): ½mv0² − ½m(5v0/7)² − ½(2/5 mR²)(5v0/7R)².
    using Law = ContactLaw<NormalHertz, TangentialMindlin>;
    Particles p;
    p.add({0, 0, r}, r, rho);
    Simulation sim(p, Law(material(0.5, 0)), {PlaneWall{}}, Vec3(0, 0, -g), 2e-6, 0.1 * r);
    for (int n = 0; n < 20000; ++n) sim.step();  // settle on the plane
    const Energy rest = sim.energy();
    const double v0 = 0.2, m = sim.particles().mass[0];
    sim.particles().velocity[0] = Vec3(v0, 0, 0);
    for (int n = 0; n < 20000; ++n) sim.step();  // slipping lasts 2 v0 / (7 mu g) = 12 ms
    const Energy e = sim.energy();
    CHECK(e.dissipated.friction - rest.dissipated.friction == Approx(m * v0 * v0 / 7).epsilon(0.01));
    CHECK(e.dissipated.rolling == 0);
}

template <class Rolling>
void check_rolling_loss() {
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, Rolling>;
    const double mu_r = 0.1, v = 0.05;
    Particles p;
    p.add({0, 0, r}, r, rho);
    Simulation sim(p, Law(material(0.5, mu_r)), {PlaneWall{}}, Vec3(0, 0, -g), 2e-6, 0.1 * r);
    for (int n = 0; n < 20000; ++n) sim.step();
    const Energy rest = sim.energy();
    const double m = sim.particles().mass[0], x0 = sim.particles().position[0].x();
    sim.particles().velocity[0] = Vec3(v, 0, 0);
    sim.particles().angular_velocity[0] = Vec3(0, v / r, 0);
    for (int n = 0; n < 50000; ++n) sim.step();  // stops after 2 v / (1.4 mu_r g)... about 36 ms
    const Energy e = sim.energy();
    CHECK(e.dissipated.rolling - rest.dissipated.rolling == Approx(0.7 * m * v * v).epsilon(0.02));
    CHECK(sim.particles().position[0].x() - x0 == Approx(0.7 * v * v / (mu_r * g)).epsilon(0.02));
}

TEST_CASE("Plastic rolling resistance dissipates all the energy of a rolling sphere", "[dem][energy]") {
    // Rolling at v: kinetic ½mv² + ½(2/5 mR²)(v/R)² = 7/10 m v², all of it lost to the rolling torque
    // mu_r R m g over the distance 7 v² / (10 mu_r g). Both rolling laws.
    check_rolling_loss<RollingEpsd>();
    check_rolling_loss<RollingConstantTorque>();
    check_rolling_loss<RollingEpsd2>();
}

TEST_CASE("The ledger does not change the physics: with and without it, the same bits", "[dem][energy]") {
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, RollingEpsd>;
    const Law law(material(0.5, 0.1));
    Simulation<Law, true> booked(column(120), law, {PlaneWall{}}, Vec3(0, 0, -g), 1e-5, 0.2 * r);
    Simulation<Law, false> plain(column(120), law, {PlaneWall{}}, Vec3(0, 0, -g), 1e-5, 0.2 * r);
    for (int n = 0; n < 3000; ++n) booked.step(), plain.step();
    CHECK(booked.particles().position == plain.particles().position);
    CHECK(booked.particles().angular_velocity == plain.particles().angular_velocity);
    CHECK(booked.energy().dissipated.total() > 0);
    CHECK(plain.energy().dissipated.total() == 0);  // nothing booked
    CHECK(booked.energy().kinetic == plain.energy().kinetic);
    // Without the ledger a pair's history drops the two springs' last stiffnesses (8 bytes each).
    CHECK(sizeof(Law::StateFor<NoDissipation>) + 16 == sizeof(Law::StateFor<Dissipation>));
}

namespace {
// Every mechanism books its own loss; what is left over is the integrator's error, first order in
// dt (dashpots are booked with the mid-step velocity). A loss booked wrongly would not shrink with dt.
template <class Law>
void check_ledger(const Law& law, const char* scene, bool lossy_cohesion = false) {
    Energy end;
    const double coarse = ledger_drift(law, 1e-5, end), fine = ledger_drift(law, 0.5e-5, end);
    const auto& d = end.dissipated;
    INFO(scene << ": drift " << coarse << " at dt = 1e-5 s, " << fine << " at 5e-6 s; lost to normal damping "
               << d.normal_damping << " J, friction " << d.friction << ", rolling " << d.rolling << ", bridges " << d.bridge
               << ", spring stiffness " << d.spring_stiffness << "; wall work " << end.wall_work);
    CHECK(coarse < 0.03);
    CHECK(fine < 0.6 * coarse);
    CHECK(d.friction > 0.2 * d.total());  // the scene exercises every mechanism it has
    CHECK(end.wall_work > 0.05 * d.total());
    if (lossy_cohesion) CHECK(d.bridge > 0.1 * d.total());
    CHECK(std::abs(d.spring_stiffness) < 0.1 * d.total());
}
}  // namespace

TEST_CASE("Energy ledger balances for a dry column collapsing from a lifted tube", "[dem][energy]") {
    check_ledger(ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, RollingEpsd>(material(0.5, 0.1)), "dry");
}

TEST_CASE("Energy ledger balances for a wet column collapsing from a lifted tube", "[dem][energy][bridge][slow]") {
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionLiquidBridge, RollingEpsd>;
    const double vhat = 0.05544;  // Eq. 5 at 4.5 % moisture (docs/model.md)
    const auto k = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}});
    const auto wall = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}}, {}, bridge::BridgeGeometry::sphere_wall);
    check_ledger(Law(material(0.5, 0.1), CohesionLiquidBridge{k, r, 0.074, wall}), "wet", true);
}

TEST_CASE("Energy ledger balances for a wet column on exact (tabulated) bridges to spheres and walls", "[dem][energy][bridge][curve][slow]") {
    // The tabulated curve's potential is its own interpolant integrated (Gauss-Legendre per
    // segment): a mismatch with the force it applies would leave a drift that does not shrink with dt.
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionLiquidBridge, RollingEpsd>;
    const double vhat = 0.05544;
    const ContactAngle theta{Degrees{20}};
    const auto k = bridge::BridgeCurve::exact(vhat, theta, bridge::BridgeGeometry::sphere_sphere);
    const auto wall = bridge::BridgeCurve::exact(vhat, theta, bridge::BridgeGeometry::sphere_wall);
    check_ledger(Law(material(0.5, 0.1), CohesionLiquidBridge{k, r, 0.074, wall}), "exact wet", true);
}

TEST_CASE("Energy ledger balances for a viscous wet column: the bridge's lubrication is booked as lost",
          "[dem][energy][bridge][viscous][slow]") {
    // μ = 0.05 Pa s (a light oil, 50× water) so that lubrication is a large share of the loss: a
    // normal or tangential part booked wrongly would leave a drift that does not shrink with dt.
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionLiquidBridge, RollingEpsd>;
    const double vhat = 0.05544;
    const auto k = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}});
    const auto wall = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{0}}, {}, bridge::BridgeGeometry::sphere_wall);
    check_ledger(Law(material(0.5, 0.1), CohesionLiquidBridge{k, r, 0.074, wall, 0.05, 0.01 * r}), "viscous wet", true);
}

TEST_CASE("Energy ledger balances for an adhesive (SJKR) column: the adhesion stores, never loses", "[dem][energy][adhesion][slow]") {
    // k = 5e4 J/m³ pulls a resting pair with about its Hertz force at the column's overlaps.
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionSjkr, RollingEpsd>;
    check_ledger(Law(material(0.5, 0.1), CohesionSjkr{5e4}), "adhesive");
}
