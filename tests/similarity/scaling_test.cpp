// Similarity algebra against dimensional analysis done by hand and the scale-factor table of
// docs/model.md §4 (Feng & Owen 2014 basis L, rho, T).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "core/input_error.hpp"
#include "similarity/quantity_catalogue.hpp"
#include "similarity/scaling_choice.hpp"

using namespace demscale;
using namespace demscale::similarity;

TEST_CASE("Catalogue dimensions equal those derived from SI units by hand", "[similarity][catalogue]") {
    // kg = rho L^3; N = kg m s^-2 = rho L^4 T^-2; Pa = N/m^2 = rho L^2 T^-2; J = rho L^5 T^-2;
    // N/m = rho L^3 T^-2; N s/m = rho L^3 T^-1; Pa s = rho L^2 T^-1; kg m^2 = rho L^5.
    const std::map<std::string, Dimension> expected = {
        {"length", {1, 0, 0}},          {"mass", {3, 1, 0}},          {"time", {0, 0, 1}},
        {"velocity", {1, 0, -1}},       {"gravity", {1, 0, -2}},      {"force", {4, 1, -2}},
        {"stress", {2, 1, -2}},         {"youngs_modulus", {2, 1, -2}}, {"energy", {5, 1, -2}},
        {"normal_stiffness", {3, 1, -2}}, {"tangential_stiffness", {3, 1, -2}},
        {"damping_coefficient", {3, 1, -1}}, {"surface_tension", {3, 1, -2}}, {"viscosity", {2, 1, -1}},
        {"moment_of_inertia", {5, 1, 0}}, {"liquid_volume", {3, 0, 0}}, {"time_step", {0, 0, 1}},
        {"friction_coefficient", {0, 0, 0}}, {"torque", {5, 1, -2}}, {"angular_velocity", {0, 0, -1}},
    };
    for (const auto& [key, dim] : expected) {
        INFO(key);
        CHECK(find_quantity(key, "test").dimension == dim);
    }
}

TEST_CASE("Scale factors of docs/model.md §4 for the two classic bases", "[similarity][basis]") {
    const double s = 2.74;
    // Gravity kept: S_rho = 1, S_T = S_L^(1/2). Velocity kept: S_rho = 1, S_T = S_L.
    const std::map<std::string, std::pair<double, double>> exponent_of_sl = {
        {"length", {1, 1}},          {"mass", {3, 3}},          {"velocity", {0.5, 0}},
        {"gravity", {0, -1}},        {"force", {3, 2}},         {"stress", {1, 0}},
        {"youngs_modulus", {1, 0}},  {"normal_stiffness", {2, 1}}, {"damping_coefficient", {2.5, 2}},
        {"surface_tension", {2, 1}}, {"time_step", {0.5, 1}},  {"energy", {4, 3}},
    };
    const ScalingChoice g_kept{{s, 1, std::sqrt(s)}, {}};
    const ScalingChoice v_kept{{s, 1, s}, {}};
    for (const auto& rows : {std::pair{&g_kept, 0}, std::pair{&v_kept, 1}}) {
        for (const auto& q : evaluate_scaling(*rows.first)) {
            auto it = exponent_of_sl.find(std::string(q.quantity->key));
            if (it == exponent_of_sl.end()) continue;
            const double e = rows.second == 0 ? it->second.first : it->second.second;
            INFO(q.quantity->key << " basis " << rows.second);
            CHECK(q.required == Approx(std::pow(s, e)).epsilon(1e-12));
            CHECK_FALSE(q.broken);
        }
    }
}

TEST_CASE("The basis is solved from two kept quantities", "[similarity][basis]") {
    // Keep g and rho at S_L = 4: S_L/S_T^2 = 1 -> S_T = 2.
    auto b = basis_keeping(4.0, "gravity", "density");
    CHECK(b.length == Approx(4.0));
    CHECK(b.density == Approx(1.0));
    CHECK(b.time == Approx(2.0));
    // Keep velocity and density: S_T = S_L.
    b = basis_keeping(3.0, "velocity", "density");
    CHECK(b.time == Approx(3.0));
    // Keep stress and gravity at S_L = 2: rho L^2 T^-2 = 1 and L T^-2 = 1 -> S_T = sqrt 2, S_rho = 1/2.
    b = basis_keeping(2.0, "stress", "gravity");
    CHECK(b.time == Approx(std::sqrt(2.0)));
    CHECK(b.density == Approx(0.5));
    // Stress and Young's modulus are the same dimension: they cannot fix two unknowns.
    CHECK_THROWS_AS(basis_keeping(2.0, "stress", "youngs_modulus"), InputError);
    CHECK_THROWS_WITH(basis_keeping(2.0, "gravty", "density"), Catch::Matchers::Contains("did you mean gravity"));
}

TEST_CASE("Partial similarity: a held quantity breaks similarity exactly when its factor is not 1",
          "[similarity][partial]") {
    // g held, basis with S_T = S_L (velocity kept): g demands 1/S_L -> broken.
    auto rows = evaluate_scaling({{2.0, 1.0, 2.0}, {"gravity", "youngs_modulus"}});
    std::map<std::string, QuantityScaling> by_key;
    for (const auto& r : rows) by_key[std::string(r.quantity->key)] = r;
    CHECK(by_key["gravity"].broken);
    CHECK(by_key["gravity"].applied == 1.0);
    CHECK(by_key["gravity"].required == Approx(0.5));
    CHECK_FALSE(by_key["youngs_modulus"].broken);  // stress demands S_rho S_L^2 / S_T^2 = 1
    CHECK_FALSE(by_key["force"].held);
    // The same held g under the gravity-kept basis is consistent.
    for (const auto& r : evaluate_scaling({basis_keeping(2.0, "gravity", "density"), {"gravity"}}))
        CHECK_FALSE(r.broken);
    CHECK_THROWS_AS(evaluate_scaling({{2.0, 1.0, 1.0}, {"no_such_quantity"}}), InputError);
    CHECK_THROWS_AS(evaluate_scaling({{0.0, 1.0, 1.0}, {}}), InputError);
}
