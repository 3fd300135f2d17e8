// Simplified JKR adhesion against independent sources: the area of the circle where two spheres
// (or a sphere and a plane) cut each other from solid geometry, its potential by quadrature, and
// one engine step at a fixed sliding contact by hand (Hertz, Mindlin at its Coulomb limit,
// torques, the spring's state).
#include <catch2/catch.hpp>
#include <cmath>

#include "dem/law_parts.hpp"
#include "dem/simulation.hpp"

using namespace demscale;
using namespace demscale::dem;

namespace {
constexpr double r = 1e-3, k = 5e4;  // m, J/m³
const CohesionSjkr sjkr{k};

// Radius² of the circle where spheres of radii a and b, centres d apart, intersect (solid
// geometry: the radical plane), and where a sphere of radius a cuts a plane at depth δ. Both lose
// digits to cancellation at small δ: about 1e-10 relative at δ = 1e-6 R.
double cut_circle2(double a, double b, double d) {
    const double x = (d * d - b * b + a * a) / (2 * d);  // from a's centre to the radical plane
    return a * a - x * x;
}
double cut_circle2_plane(double a, double delta) { return a * a - (a - delta) * (a - delta); }

double pull(double overlap, bool wall) {
    CohesionSjkr::State s;
    NoDissipation none;
    return sjkr.pull(overlap, r, 0.0, 1e-6, wall, s, none);
}
}  // namespace

TEST_CASE("SJKR adhesion pulls with k times the cut circle's area, nothing across a gap", "[dem][adhesion]") {
    for (double hat : {1e-6, 1e-4, 1e-2, 0.1}) {
        INFO("overlap " << hat << " R");
        const double delta = hat * r;
        CHECK(pull(delta, false) == Approx(k * M_PI * cut_circle2(r, r, 2 * r - delta)).epsilon(1e-9));
        CHECK(pull(delta, true) == Approx(k * M_PI * cut_circle2_plane(r, delta)).epsilon(1e-9));
    }
    CHECK(pull(0.0, false) == 0);
    CHECK(pull(-1e-6, false) == 0);
    CHECK(pull(-1e-6, true) == 0);
    CHECK(sjkr.range() == 0);
}

TEST_CASE("SJKR adhesion's potential is minus the work of its pull (Simpson quadrature)", "[dem][adhesion][energy]") {
    for (const bool wall : {false, true}) {
        const double delta = 0.05 * r;
        const int n = 200;  // Simpson on a cubic: exact up to rounding
        double work = pull(0, wall) + pull(delta, wall);
        for (int i = 1; i < n; ++i) work += (i % 2 ? 4 : 2) * pull(i * delta / n, wall);
        work *= delta / n / 3;
        ContactPair c;
        c.overlap = delta, c.r_harmonic = r, c.wall = wall;
        INFO((wall ? "wall" : "spheres"));
        CHECK(sjkr.stored_energy(c, {}) == Approx(-work).epsilon(1e-12));
    }
}

TEST_CASE("SJKR in the engine: one step of a sliding contact by hand (force, torques, spring state)", "[dem][adhesion]") {
    using Law = ContactLaw<NormalHertz, TangentialMindlin, CohesionSjkr>;
    Material m;  // E = 5 MPa, ν = 0.3, μ = 0.5
    const double delta = 2e-3 * r, v = 1, dt = 1e-5, rho = 2200;
    Particles p;
    p.add({0, 0, 0}, r, rho);
    p.add({2 * r - delta, 0, 0}, r, rho, Vec3(0, v, 0));  // sliding along y, no normal motion
    Simulation sim(p, Law(m, sjkr), {}, Vec3::Zero(), dt, 0.1 * r);
    // Hertz with R* = R/2 (no damping: v_n = 0), the cut circle's pull with R, and the tangential
    // spring: v dt = 10 µm of slip is far beyond μF_n / S_t, so the force sits at μ F_hertz —
    // the Coulomb limit sees the contact force without the adhesion (LIGGGHTS' tangential_reduce on).
    const double e_star = m.youngs_modulus / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
    const double g_star = m.youngs_modulus / (4 * (2 - m.poisson_ratio) * (1 + m.poisson_ratio));
    const double hertz = 4.0 / 3.0 * e_star * std::sqrt(r / 2) * std::pow(delta, 1.5);
    const double adhesion = k * M_PI * (r * delta - delta * delta / 4);
    const double s_t = 8 * g_star * std::sqrt(r / 2 * delta);
    REQUIRE(s_t * v * dt > 10 * m.friction * hertz);  // sliding
    const double friction = m.friction * hertz, lever = r - delta / 2;
    const auto& q = sim.particles();
    CHECK(q.force[0].x() == Approx(-(hertz - adhesion)).epsilon(1e-12));  // pushed along −x by the net normal force
    CHECK(q.force[0].y() == Approx(friction).epsilon(1e-12));             // dragged along +y by the slider
    CHECK(q.force[1].x() == Approx(hertz - adhesion).epsilon(1e-12));
    CHECK(q.force[1].y() == Approx(-friction).epsilon(1e-12));
    CHECK(q.torque[0].z() == Approx(lever * friction).epsilon(1e-12));
    CHECK(q.torque[1].z() == Approx(lever * friction).epsilon(1e-12));
    CHECK(std::abs(q.force[0].z()) + std::abs(q.torque[0].x()) + std::abs(q.torque[0].y()) < 1e-15);
    // The state the step left: the slipping spring reset to the limit, ξ = −F_t / S_t, holds
    // ½ F_t² / S_t; the adhesion holds −k_c π (R δ²/2 − δ³/12); Hertz 8/15 E* √R* δ^(5/2).
    const StoredEnergy held = sim.energy().stored;
    CHECK(held.tangential == Approx(0.5 * friction * friction / s_t).epsilon(1e-12));
    CHECK(held.bridge == Approx(-k * M_PI * (r * delta * delta / 2 - delta * delta * delta / 12)).epsilon(1e-12));
    CHECK(held.normal == Approx(8.0 / 15.0 * e_star * std::sqrt(r / 2) * std::pow(delta, 2.5)).epsilon(1e-12));
    // A sphere resting at depth δ on a plane: Hertz with R* = R, the plane's cut circle.
    Particles one;
    one.add({0, 0, r - delta}, r, rho);
    Simulation on_floor(one, Law(m, sjkr), {PlaneWall{}}, Vec3::Zero(), dt, 0.1 * r);
    const double hertz_wall = 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(delta, 1.5);
    CHECK(on_floor.particles().force[0].z() == Approx(hertz_wall - k * M_PI * delta * (2 * r - delta)).epsilon(1e-12));
}

TEST_CASE("SJKR adhesion is a dry scene's cohesion: the scene reader refuses it in a wet one", "[dem][adhesion][parameters]") {
    ContactSettings s;
    s.cohesion_energy_density = 1e4;
    CHECK_FALSE(sjkr_part.active(s));  // wet by default
    CHECK_FALSE(sjkr_part.allowed(s));
    s.wet = false;
    CHECK(sjkr_part.active(s));
    CHECK(sjkr_part.allowed(s));
    s.cohesion_energy_density = 0;
    CHECK_FALSE(sjkr_part.active(s));  // k = 0: the dry law, no adhesion code in the force loop
}
