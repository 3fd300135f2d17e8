#include <catch2/catch.hpp>
#include <cmath>

#include "bridge/liquid_volume.hpp"
#include "core/input_error.hpp"

using namespace demscale;

TEST_CASE("Eq. 5: liquid volume per bridge from moisture content", "[bridge][eq5]") {
    // 1 - sqrt(3/4) = 1 - 0.8660254 = 0.1339746
    CHECK(bridge::eq5_bridge_fraction == Approx(1.0 - std::sqrt(0.75)).epsilon(1e-15));
    // R = 1 mm row of Table 1: m = 0.01 g = 1e-5 kg, phi = 0.045, rho = 1000:
    // V = 0.045 * 1e-5 / 1000 * 0.1339746 = 6.02886e-11 m^3 -> V^ = 0.0602886 (docs/model.md: 0.06029)
    CHECK(bridge::liquid_bridge_volume(0.045, 1e-5, 1000.0) == Approx(6.02886e-11).epsilon(1e-5));
    CHECK_THROWS_AS(bridge::liquid_bridge_volume(0.0, 1e-5, 1000.0), InputError);
    CHECK_THROWS_AS(bridge::liquid_bridge_volume(1.0, 1e-5, 1000.0), InputError);
    CHECK_THROWS_AS(bridge::liquid_bridge_volume(0.045, -1.0, 1000.0), InputError);
    CHECK_THROWS_AS(bridge::liquid_bridge_volume(0.045, 1e-5, std::nan("")), InputError);
}
