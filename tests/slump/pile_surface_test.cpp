// The pile's surface and the measures drawn from it: the exact section areas (closed forms and
// the conservation of each sphere's volume), and piles of one shape (a cone, a flat layer, a
// Gaussian mound) built from spheres of R, 1.4 R, 1.96 R and 2.74 R, which must measure the same
// height and spread where the sphere-level measures do not.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <random>

#include "dem/sphere_grid.hpp"
#include "slump/measurements.hpp"
#include "slump/pile_surface.hpp"

using namespace demscale;
using namespace demscale::slump;

namespace {

using Shape = std::function<double(double)>;  // surface height at radius ρ, m

// A random packing of equal spheres (random sequential addition to a solid fraction of 0.3 in a box
// wider and taller than every shape, so its walls lie outside them), cut by the shape through the
// centres and resting on the floor: centres with R ≤ z ≤ h(ρ). The same shape at any radius.
dem::Particles packing(double r, unsigned seed, double reach, double height) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    const double half = reach + 4 * r, z0 = -4 * r, z1 = height + 4 * r;
    const auto want = static_cast<std::size_t>(0.3 * 4 * half * half * (z1 - z0) / (4.0 / 3.0 * M_PI * r * r * r));
    dem::SphereGrid grid(2 * r);
    dem::Particles p;
    for (std::size_t tries = 0; p.size() < want && tries < 50 * want; ++tries) {
        const dem::Vec3 x(half * (2 * u(rng) - 1), half * (2 * u(rng) - 1), z0 + (z1 - z0) * u(rng));
        if (grid.any_within(x, 2 * r)) continue;
        grid.add(x);
        p.add(x, r, 2500);
    }
    return p;
}

dem::Particles cut(const dem::Particles& box, const Shape& h) {
    dem::Particles p;
    for (std::size_t i = 0; i < box.size(); ++i) {
        const auto& x = box.position[i];
        if (x.z() >= box.radius[i] && x.z() <= h(std::hypot(x.x(), x.y()))) p.add(x, box.radius[i], 2500);
    }
    return p;
}

const SurfaceGrid grid{19e-3 / 16, 19e-3 / 2};  // the reference cone's: a 19 mm top opening

}  // namespace

TEST_CASE("Disc overlap: the closed forms of disjoint, nested and equal discs", "[slump][surface]") {
    CHECK(disc_overlap_area(1, 2, 3.5) == 0);
    CHECK(disc_overlap_area(1, 3, 1.5) == Approx(M_PI));          // the small disc inside the large one
    CHECK(disc_overlap_area(3, 1, 0) == Approx(M_PI));
    for (double d : {0.3, 1.0, 1.7}) {  // two unit discs: 2 acos(d/2) − (d/2) √(4 − d²)
        INFO("d = " << d);
        CHECK(disc_overlap_area(1, 1, d) == Approx(2 * std::acos(d / 2) - 0.5 * d * std::sqrt(4 - d * d)));
    }
    // Unequal discs against a count of grid points inside both (second method).
    const double a = 1.0, b = 0.6, d = 1.2, step = 2e-3;
    double inside = 0;
    for (double x = -1; x <= 1; x += step)
        for (double y = -1; y <= 1; y += step)
            if (x * x + y * y <= a * a && (x - d) * (x - d) + y * y <= b * b) inside += step * step;
    CHECK(disc_overlap_area(a, b, d) == Approx(inside).epsilon(2e-3));
}

TEST_CASE("Pile surface: the annuli hold each sphere's volume, and heights times the bulk give it back",
          "[slump][surface]") {
    // Spheres anywhere across annulus edges: Σ φ·area·dz is their volume (conservation).
    dem::Particles p;
    const double r = 1e-3;
    p.add({0.0003, 0.0002, 0.0028}, r, 2500), p.add({0.0061, -0.0023, 0.0016}, r, 2500), p.add({-0.0102, 0.0057, 0.0011}, r, 2500);
    const auto s = pile_surface(p, 0, 0, grid);
    // heights × area × bulk = the solid, for columns lower than 4 R (integrated from the floor)
    double solid = 0;
    for (std::size_t b = 0; b < s.radii.size(); ++b) {
        const double w = grid.bin_width, area = M_PI * w * w * (2 * static_cast<double>(b) + 1);
        solid += s.heights[b] * s.bulk_fraction * area;
    }
    CHECK(solid == Approx(3 * 4.0 / 3.0 * M_PI * r * r * r).epsilon(5e-3));
    CHECK_THROWS(pile_surface(p, 0, 0, {0, 1e-3}));
}

TEST_CASE("Size-independent measures: one shape built from spheres of R to 2.74 R measures the same height and spread",
          "[slump][surface][slow]") {
    // Each shape, each radius, 8 seeds; the means over the seeds are compared with those at R. The
    // tolerances are what these loose random packings reach (docs/slump-measures.md): the seed noise
    // of a 2.74 R pile's height is about 1.2 mm, so its mean of 8 is good to about 0.4 mm.
    struct Case {
        const char* name;
        Shape h;
        double reach, top;
    };
    const Case shapes[] = {{"cone", [](double q) { return 0.03 * (1 - q / 0.045); }, 0.045, 0.03},
                           {"flat layer", [](double q) { return q < 0.04 ? 0.02 : 0.0; }, 0.04, 0.02},
                           {"Gaussian mound", [](double q) { return 0.03 * std::exp(-q * q / (2 * 0.015 * 0.015)); }, 0.06, 0.03}};
    const double fine = 1e-3;
    const int seeds = 8;
    struct Mean {
        double height = 0, spread = 0, top = 0;
    };
    std::vector<std::vector<Mean>> means(3);
    for (double sf : {1.0, 1.4, 1.96, 2.74}) {
        std::vector<Mean> m(3);
        for (int seed = 1; seed <= seeds; ++seed) {
            const auto box = packing(sf * fine, static_cast<unsigned>(seed), 0.06, 0.03);
            for (std::size_t c = 0; c < 3; ++c) {
                const auto pile = measure_pile(cut(box, shapes[c].h), 2 * sf * fine, grid);
                m[c].height += pile.height / seeds, m[c].spread += pile.spread / seeds, m[c].top += pile.height_top / seeds;
            }
        }
        for (std::size_t c = 0; c < 3; ++c) means[c].push_back(m[c]);
    }
    const double sfs[] = {1.0, 1.4, 1.96, 2.74};
    // Reached here: 0.5 %, 1.9 % and 3.1 % of the height at 1.4, 1.96 and 2.74 R; spreads within 2.4 %.
    const double height_tol[] = {0, 0.01, 0.025, 0.04};  // of the height at R
    for (std::size_t c = 0; c < 3; ++c) {
        const auto& at_r = means[c][0];
        for (std::size_t k = 1; k < 4; ++k) {
            const auto& m = means[c][k];
            INFO(shapes[c].name << " at " << sfs[k] << " R: height " << m.height * 1e3 << " mm (at R " << at_r.height * 1e3
                                << "), spread " << m.spread * 1e3 << " mm (at R " << at_r.spread * 1e3 << "), highest top "
                                << m.top * 1e3 << " mm (at R " << at_r.top * 1e3 << ")");
            CHECK(std::abs(m.height - at_r.height) <= height_tol[k] * at_r.height);
            CHECK(std::abs(m.spread - at_r.spread) <= 0.035 * at_r.spread);
        }
    }
    // The sphere-level height it replaces grows with the radius where the top is wide: the coarsest flat
    // layer's highest top stands (2.74 − 1) R higher, about; at a peak, fewer coarse spheres reach up.
    CHECK(means[1][3].top - means[1][0].top > 0.5 * (2.74 - 1) * fine);
    // The surface is where the cut is: the flat layer at R measures its 20 mm.
    CHECK(means[1][0].height == Approx(0.02).epsilon(0.01));
}

TEST_CASE("Repose angle from the surface's flank: constructed cones of 20 and 35 degrees", "[slump][surface]") {
    const double r = 1e-3, H = 0.02;
    for (double alpha_deg : {20.0, 35.0}) {
        const double t = std::tan(alpha_deg * M_PI / 180), base = H / t;
        const auto box = packing(r, 3, base, H);
        const auto m = measure_pile(cut(box, [&](double q) { return H - q * t; }), 2 * r, grid);
        INFO("alpha = " << alpha_deg << ": measured " << m.repose_angle_deg.value_or(-1) << ", height " << m.height * 1e3 << " mm");
        CHECK(m.repose_angle_deg.value() == Approx(alpha_deg).margin(2.0));
        // The mean over the axis disc of radius a: H − (2/3) a tan(alpha).
        CHECK(m.height == Approx(H - 2.0 / 3.0 * grid.axis_radius * t).epsilon(0.02));
    }
}
