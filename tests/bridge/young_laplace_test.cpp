// The exact Young–Laplace bridge against independent references: a second integration method
// (quadrature of the first integral), closed-form limits, the toroidal approximation, published
// values and the rupture laws of Lian et al. (1993) and Willett et al. (2000).
#include <catch2/catch.hpp>
#include <cmath>

#include "bridge/closed_forms.hpp"
#include "bridge/mikami.hpp"
#include "bridge/young_laplace.hpp"

using namespace demscale;
using namespace demscale::bridge;

namespace {
const ContactAngle zero{Degrees{0}};
}

TEST_CASE("Exact bridge: volume and gap equal the request, checked by an independent quadrature", "[bridge][exact]") {
    for (double vhat : {1e-5, 1e-3, 0.05544, 0.3}) {
        for (double deg : {0.0, 30.0}) {
            const ContactAngle theta{Degrees{deg}};
            const YoungLaplaceBridge bridge(vhat, theta);
            REQUIRE(bridge.family_ok());
            for (double x : {0.0, 0.5, 0.95}) {
                const double hhat = x * bridge.hhat_rupture();
                const auto r = bridge.solve(hhat);
                INFO("vhat=" << vhat << " theta=" << deg << " x=" << x);
                REQUIRE(r.ok());
                // d and V recomputed from (beta, r0) by GSL QAGS on dz/dr of the first integral.
                const auto [half_gap, volume] = bridge_by_quadrature(r.shape.filling_angle, r.shape.neck_radius, theta);
                CHECK(std::abs(volume - vhat) / vhat < 1e-8);
                CHECK(std::abs(half_gap - hhat / 2) < 1e-9 * std::max(1.0, hhat));
                // Axial force at the neck and at the contact line (with the integrated angle) agree.
                CHECK(std::abs(r.shape.fhat_neck - r.shape.fhat_contact) < 1e-9);
                CHECK(r.shape.contact_angle_error < 1e-8);
            }
        }
    }
}

TEST_CASE("Exact bridge: small-volume limit F/(2 pi R gamma) -> cos(theta) at contact, from below", "[bridge][exact]") {
    // As V^ -> 0 the bridge at contact pulls with 2 pi R gamma cos(theta) (Fisher 1926; docs/model.md §3: 0.9937 at 1e-7).
    for (double deg : {0.0, 30.0, 60.0}) {
        const ContactAngle theta{Degrees{deg}};
        double previous = 0;
        for (double vhat : {1e-2, 1e-4, 1e-6}) {
            const auto r = solve_young_laplace(vhat, theta, 0.0);
            REQUIRE(r.ok());
            INFO("theta=" << deg << " vhat=" << vhat);
            CHECK(r.shape.fhat_neck < std::cos(theta.radians()));
            CHECK(r.shape.fhat_neck > previous);  // approaches the limit monotonically
            previous = r.shape.fhat_neck;
        }
        CHECK(previous == Approx(std::cos(theta.radians())).epsilon(0.03));
    }
}

TEST_CASE("Exact bridge: published value at V^ = 1e-4, theta = 0, contact", "[bridge][exact]") {
    // docs/model.md §2 [V]: exact F/(pi R gamma) = 1.929 (independent Young-Laplace implementation).
    const auto r = solve_young_laplace(1e-4, zero, 0.0);
    REQUIRE(r.ok());
    CHECK(2 * r.shape.fhat_neck == Approx(1.929).margin(0.0006));
}

TEST_CASE("Exact bridge against the toroidal approximation in its limit (small V^, contact)", "[bridge][exact][toroidal]") {
    // Toroidal (Lian et al. 1993) is exact as V^ -> 0 and under-predicts slightly (docs/model.md §3: -6 ... -0.5 %).
    const double exact_small = solve_young_laplace(1e-5, zero, 0.0).shape.fhat_neck;
    CHECK(toroidal_bridge(1e-5, zero, 0.0).fhat / exact_small - 1 == Approx(0).margin(0.01));
    const double exact_mid = solve_young_laplace(0.05544, zero, 0.0).shape.fhat_neck;
    const double rel = toroidal_bridge(0.05544, zero, 0.0).fhat / exact_mid - 1;
    CHECK(rel < 0);
    CHECK(rel > -0.06);
}

TEST_CASE("Exact bridge against Willett et al. (2000)'s full fit away from rupture", "[bridge][exact][willett]") {
    // Willett's fit of their own numerical solutions; measured here: within 7.0 % for theta = 0,
    // 3e-5 <= V^ <= 0.1, h^ <= 0.8 h^_c (worst near 0.8 h^_c). Asserted: 8 %.
    for (double vhat : {3e-5, 1e-3, 0.05}) {
        const YoungLaplaceBridge bridge(vhat, zero);
        for (double x : {0.0, 0.2, 0.4, 0.6, 0.8}) {
            const double hhat = x * bridge.hhat_rupture();
            const double exact = bridge.solve(hhat).shape.fhat_neck;
            INFO("vhat=" << vhat << " x=" << x);
            CHECK(std::abs(willett_full_fhat(vhat, zero, hhat) / exact - 1) < 0.08);
        }
    }
}

TEST_CASE("Exact rupture distance against Willett Eq. 15 and Lian's (1 + theta/2) V^(1/3)", "[bridge][exact][rupture]") {
    // Measured: theta = 0, V^ <= 0.06: within 0.3 % of Willett Eq. 15 and 0.4-3.7 % above Lian.
    // Lian's law is itself approximate: up to +21 % at theta = 60 deg, V^ = 0.3 (reported, not asserted).
    for (double vhat : {1e-5, 1e-3, 0.05544}) {
        const auto r = young_laplace_rupture(vhat, zero);
        REQUIRE(r.has_value());
        INFO("vhat=" << vhat);
        CHECK(std::abs(r->hhat / willett_rupture_hhat(vhat, zero) - 1) < 0.005);
        CHECK(std::abs(r->hhat / rupture_hhat(vhat, zero, RuptureLaw::lian1993) - 1) < 0.05);
    }
    const ContactAngle t30{Degrees{30}};
    for (double vhat : {1e-5, 1e-3, 0.05544})
        CHECK(std::abs(young_laplace_rupture(vhat, t30)->hhat / rupture_hhat(vhat, t30, RuptureLaw::lian1993) - 1) < 0.05);
}

TEST_CASE("Exact bridge hard cases: clear statuses, never NaN", "[bridge][exact][hard]") {
    for (double vhat : {1e-6, 0.5}) {
        for (double deg : {0.0, 80.0}) {
            const auto r = solve_young_laplace(vhat, ContactAngle{Degrees{deg}}, 0.0);
            INFO("vhat=" << vhat << " theta=" << deg << " " << r.message);
            if (r.ok()) {
                CHECK(std::isfinite(r.shape.fhat_neck));
                CHECK(r.shape.fhat_neck > 0);
                CHECK(r.shape.fhat_neck < std::cos(ContactAngle{Degrees{deg}}.radians()) + 1e-12);
            } else {
                CHECK_FALSE(r.message.empty());  // V^ = 0.5 at 80 deg bulges: outside the concave scope
            }
        }
    }
    const YoungLaplaceBridge bridge(1e-3, zero);
    const double hc = bridge.hhat_rupture();
    const auto below = bridge.solve(hc * (1 - 1e-9));
    REQUIRE(below.ok());
    CHECK(below.shape.fhat_neck > 0);
    const auto above = bridge.solve(hc * (1 + 1e-9));
    CHECK(above.status == YoungLaplaceStatus::above_rupture);
    CHECK(above.shape.fhat_neck == 0.0);
    CHECK(bridge.solve(-0.1).status == YoungLaplaceStatus::outside_scope);
    // Where the printed Mikami form turns negative (V^ = 1e-5), the exact bridge still pulls.
    const YoungLaplaceBridge tiny(1e-5, zero);
    CHECK(tiny.solve(0.3 * rupture_hhat(1e-5, zero, RuptureLaw::lian1993)).shape.fhat_neck > 0);
}

TEST_CASE("Exact bridge at contact angles 80-89 deg: a number or an explicit status at every grid point",
          "[bridge][exact][hard]") {
    // V^ 1e-7 ... 1e-2 at θ 80 ... 89°: where the solver finds a bridge its force lies in
    // (0, cos θ] and it holds V^; elsewhere it says why (bulging: outside the concave scope),
    // and never "did not converge". A concave bridge needs β + θ < 90°: at θ = 89° only a tiny one
    // (about V^ = (π/2) β⁴ ≈ 1.5e-7 at contact) can exist.
    int solved = 0, refused = 0;
    for (double deg : {80.0, 82.0, 84.0, 86.0, 88.0, 89.0})
        for (double vhat : {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2}) {
            const ContactAngle theta{Degrees{deg}};
            const YoungLaplaceBridge bridge(vhat, theta);
            INFO("theta " << deg << ", V^ " << vhat << ": " << bridge.family_message());
            if (!bridge.family_ok()) {
                CHECK_FALSE(bridge.family_message().empty());
                ++refused;
                continue;
            }
            for (double x : {0.0, 0.3, 0.6, 0.9, 0.99}) {
                const auto r = bridge.solve(x * bridge.hhat_rupture());
                INFO("x = " << x << ": " << r.message);
                CHECK(r.status != YoungLaplaceStatus::not_converged);
                if (!r.ok()) {
                    CHECK(r.status == YoungLaplaceStatus::outside_scope);
                    CHECK_FALSE(r.message.empty());
                    ++refused;
                    continue;
                }
                ++solved;
                CHECK(r.shape.fhat_neck > 0);
                CHECK(r.shape.fhat_neck <= std::cos(theta.radians()) * (1 + 1e-9));
                CHECK(r.shape.volume == Approx(vhat).epsilon(1e-8));
            }
        }
    CHECK(solved > 100);  // most of the grid has a bridge
    CHECK(refused > 0);   // and the large volumes at 88-89° do not
    // The cases that failed before: θ = 80°, V^ ≤ 1e-4 away from contact; θ = 85°, V^ = 1e-6 at
    // contact; θ = 89°, V^ = 1e-7 (a concave bridge exists).
    CHECK(YoungLaplaceBridge(1e-4, ContactAngle{Degrees{80}}).solve(0.5 * YoungLaplaceBridge(1e-4, ContactAngle{Degrees{80}}).hhat_rupture()).ok());
    CHECK(solve_young_laplace(1e-6, ContactAngle{Degrees{85}}, 0.0).ok());
    CHECK(solve_young_laplace(1e-7, ContactAngle{Degrees{89}}, 0.0).ok());
}

TEST_CASE("Rupture at the first instability: symmetry breaking comes before the fold at large contact angles",
          "[bridge][young-laplace][symmetry]") {
    using Residual = YoungLaplaceBridge::Residual;
    // θ = 0 and 20°: the symmetric bridge stays stable up to its fold.
    for (double theta : {0.0, 20.0}) {
        const YoungLaplaceBridge b(0.05544, ContactAngle{Degrees{theta}});
        INFO("theta = " << theta);
        CHECK(b.symmetry().status == SymmetryStatus::holds_to_fold);
        CHECK(b.hhat_rupture() == b.hhat_fold());
    }
    // θ = 40°: an antisymmetric mode (liquid moving to one sphere) appears 1-4 % before the fold.
    // Two routes: the second residual measured where the meniscus meets the upper sphere, or where
    // it reaches the contact angle; they describe one solution set, so they must agree.
    // (At V^ <= 1e-3 and theta >= 35 deg the angle route lands up to 0.6 % later; it is used only
    // below 20 deg, where neither route finds symmetry breaking.)
    for (double vhat : {1e-3, 0.05544, 0.3}) {
        const YoungLaplaceBridge b(vhat, ContactAngle{Degrees{40}});
        INFO("V^ = " << vhat);
        REQUIRE(b.symmetry().status == SymmetryStatus::breaks);
        const double early = 1 - b.hhat_rupture() / b.hhat_fold();
        CHECK(early > 0.01);
        CHECK(early < 0.05);
        if (vhat > 1e-2) {
            const auto other = b.check_symmetry(Residual::by_angle);
            REQUIRE(other.status == SymmetryStatus::breaks);
            CHECK(other.hhat == Approx(b.hhat_rupture()).epsilon(1e-6));
        }
        // Between the two instabilities the symmetric shape exists but is not a stable bridge.
        const auto beyond = b.solve(0.5 * (b.hhat_rupture() + b.hhat_fold()));
        CHECK(beyond.status == YoungLaplaceStatus::above_rupture);
        CHECK(beyond.message.find("breaks symmetry") != std::string::npos);
        CHECK(b.solve(b.hhat_rupture() * (1 - 1e-9)).ok());
        CHECK(b.rupture_has_slope());
    }
}
