// Particle replacement (Eqs. 9-10) and stress similarity (Eqs. 11-12) for any exponent k.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bridge/mikami.hpp"
#include "core/input_error.hpp"
#include "similarity/particle_replacement.hpp"
#include "similarity/quantity_catalogue.hpp"
#include "similarity/stress_similarity.hpp"

using namespace demscale;
using namespace demscale::similarity;

namespace {
const Liquid water{};  // 0.074 N/m, 0 deg, 1000 kg/m^3, 4.5 %
constexpr double rho_s = 2195.17;
const double table1_sf[] = {1.0, 1.40, 1.96, 2.74, 3.84};
}  // namespace

TEST_CASE("Replacement leaves V^ invariant: proved for every S_f against the closed form", "[similarity][replacement]") {
    // V^ = V_liq / R^3 = phi (m / rho_l)(1 - sqrt(3/4)) / R^3 = phi (rho_s / rho_l)(4 pi / 3)(1 - sqrt(3/4)),
    // independent of R: 0.045 * 2.19517 * 4.18879 * 0.1339746 = 0.0554363 (docs/model.md: 0.05544).
    const double closed = 0.045 * (rho_s / 1000.0) * 4.0 / 3.0 * std::numbers::pi * (1 - std::sqrt(0.75));
    CHECK(closed == Approx(0.05544).epsilon(1e-3));
    for (double sf : {1.0, 1.4, 1.96, 2.74, 3.84, 10.0, 1e3}) {
        const auto p = replace_particle(1e-3, rho_s, sf, water);
        INFO("sf = " << sf);
        CHECK(p.vhat == Approx(closed).epsilon(1e-13));
        CHECK(p.radius_m == Approx(sf * 1e-3));
        CHECK(p.replaced_count == Approx(sf * sf * sf));
        // Eq. 10: m_bar = m S_f^3, mass conserved: one coarse particle weighs what S_f^3 fine ones do.
        const auto fine = replace_particle(1e-3, rho_s, 1.0, water);
        CHECK(p.mass_kg == Approx(fine.mass_kg * sf * sf * sf).epsilon(1e-13));
        CHECK(p.liquid_volume_m3 == Approx(fine.liquid_volume_m3 * sf * sf * sf).epsilon(1e-13));
    }
}

TEST_CASE("Rounded Table 1 masses break the invariance (why the default uses a density)", "[similarity][replacement]") {
    // R = 1.40 mm printed as 0.03 g: V^ = 0.045 * 3e-8 * 0.1339746 / (1.4e-3)^3 = 0.065913 (docs/model.md: 0.06591).
    const auto p = describe_particle(1.4, 1.4e-3, 3e-5, water);
    CHECK(p.vhat == Approx(0.065913).epsilon(1e-4));
}

TEST_CASE("Stress similarity: sigma independent of S_f exactly when k = 1, proportional to S_f^2 when k = 3",
          "[similarity][stress]") {
    const auto fine = replace_particle(1e-3, rho_s, 1.0, water);
    for (auto variant : {bridge::MikamiVariant::mikami1998, bridge::MikamiVariant::yun_park_2017}) {
        const auto k = bridge::mikami_coefficients(fine.vhat, water.contact_angle, {variant, bridge::RuptureLaw::mikami1998});
        const double fhat = bridge::mikami_fhat(k, 0.0);
        const auto s1 = stress_similarity(k, fhat, fine.radius_m, water.surface_tension_n_per_m, 1.0, 1.0);
        for (double sf : table1_sf) {
            const double r = sf * 1e-3;
            for (double kk : {0.0, 1.0, 1.5, 2.0, 3.0}) {
                const auto s = stress_similarity(k, fhat, r, water.surface_tension_n_per_m, sf, kk);
                INFO("sf=" << sf << " k=" << kk);
                CHECK(s.sigma_pa / s1.sigma_pa == Approx(std::pow(sf, kk - 1)).epsilon(1e-13));
                CHECK(s.force_n / s1.force_n == Approx(std::pow(sf, kk + 1)).epsilon(1e-13));
            }
            // Eq. 11 closed form for the printed variant: sigma = 2 F^ gamma S_f^(k-1) / R (k = 3 -> 2 F^ gamma S_f^2 / R).
            if (variant == bridge::MikamiVariant::yun_park_2017) {
                const auto s3 = stress_similarity(k, fhat, r, water.surface_tension_n_per_m, sf, 3.0);
                CHECK(s3.sigma_pa == Approx(2 * fhat * water.surface_tension_n_per_m * sf * sf / 1e-3).epsilon(1e-13));
            }
        }
    }
}

TEST_CASE("Contact stresses of docs/model.md §1 (independent computation)", "[similarity][stress]") {
    // docs/model.md: 2 pi R gamma normalisation, C = 0.0042: k = 1 -> 262.4 Pa at every S_f; k = 3 -> 1008 / 1970 / 3870 Pa
    // at S_f = 1.96 / 2.74 / 3.84. Mikami's pi R gamma gives exactly half of each.
    const auto fine = replace_particle(1e-3, rho_s, 1.0, water);
    const auto k = bridge::mikami_coefficients(fine.vhat, water.contact_angle);
    const double fhat = bridge::mikami_fhat(k, 0.0);
    CHECK(stress_similarity(k, fhat, 1e-3, 0.074, 1.0, 1.0).sigma_pa == Approx(262.4 / 2).epsilon(1e-3));
    const double expected[] = {1008, 1970, 3870};
    const double sfs[] = {1.96, 2.74, 3.84};
    for (int i = 0; i < 3; ++i)
        CHECK(stress_similarity(k, fhat, sfs[i] * 1e-3, 0.074, sfs[i], 3.0).sigma_pa == Approx(expected[i] / 2).epsilon(2e-3));
}

TEST_CASE("Exponents derived from the algebra: stress k = 1, force per mass and Bond number k = 2", "[similarity][exponent]") {
    // Hand derivation: F_bar = gamma S_f^k * S_f R * f -> F_bar/F = S_f^(k+1).
    // F/area: S_f^(k+1-2) = 1 -> k = 1.  F/mass: S_f^(k+1-3) -> k = 2.  F/(m g) with g kept: k = 2.
    // Force under exact scaling, g kept: force demands S_L^4 S_T^-2 = S_f^3 -> k = 2; velocity kept: S_f^2 -> k = 1.
    auto dim = [](const char* key) { return find_quantity(key, "test").dimension; };
    CHECK(bridge_force_exponent(3.0) == 4.0);
    CHECK(exponent_keeping_ratio(dim("area"), 0.0) == 1.0);
    CHECK(exponent_keeping_ratio(dim("mass"), 0.0) == 2.0);
    CHECK(exponent_keeping_ratio(dim("mass") * dim("gravity"), 0.5) == 2.0);
    CHECK(exponent_keeping_ratio(dim("force"), 0.5) == 2.0);
    CHECK(exponent_keeping_ratio(dim("force"), 1.0) == 1.0);
    const auto groups = bridge_similarity_groups();
    REQUIRE(groups.size() == 5);
    CHECK(groups[0].keeping_exponent == 1.0);
    CHECK(group_ratio_exponent(groups[0], 3.0) == 2.0);   // k = 3: stress grows as S_f^2 (Eq. 11)
    CHECK(group_ratio_exponent(groups[1], 1.0) == -1.0);  // k = 1: Bond number falls as 1/S_f
}

TEST_CASE("Huge S_f stays finite or fails loudly", "[similarity][hard]") {
    const auto k = bridge::mikami_coefficients(0.05544, water.contact_angle);
    const auto s = stress_similarity(k, 1.77, 1.0, 0.074, 1e3, 3.0);
    CHECK(std::isfinite(s.sigma_pa));
    CHECK(s.sigma_pa == Approx(1.77 * 0.074 * 1e9 / 1.0).epsilon(1e-12));  // pi R gamma S_f^3 F^ / (pi R^2), R = 1 m
    CHECK_THROWS_AS(stress_similarity(k, 1.77, 1e297, 0.074, 1e300, 3.0), std::overflow_error);
    CHECK_THROWS_AS(stress_similarity(k, 1.77, 1e-3, 0.074, 0.0, 3.0), InputError);
    CHECK_THROWS_AS(stress_similarity(k, 1.77, 1e-3, 0.074, 2.0, std::nan("")), InputError);
}
