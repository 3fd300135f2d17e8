// The contact loops' cross product against a hand example and Eigen's, bit for bit.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>

#include "dem/cross.hpp"

using namespace demscale::dem;

namespace {
bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }
}  // namespace

TEST_CASE("Cross product: x times y is z and every component is Eigen's to the bit", "[dem][contact]") {
    CHECK(same_bits(cross(Vec3::UnitX(), Vec3::UnitY()), Vec3::UnitZ()));
    CHECK(same_bits(cross(Vec3(1, 2, 3), Vec3(4, 5, 6)), Vec3(2 * 6 - 3 * 5, 3 * 4 - 1 * 6, 1 * 5 - 2 * 4)));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mantissa(-1, 1);
    std::uniform_int_distribution<int> exponent(-40, 40);
    auto draw = [&] {
        Vec3 v;
        for (int k = 0; k < 3; ++k) v[k] = std::ldexp(mantissa(rng), exponent(rng));
        return v;
    };
    for (int n = 0; n < 100000; ++n) {
        const Vec3 a = draw(), b = draw();
        INFO(a.transpose() << " x " << b.transpose());
        REQUIRE(same_bits(cross(a, b), a.cross(b)));
    }
    // Signed zeros come out as Eigen's too, and a NaN stays one (it must reach the engine's checks).
    CHECK(same_bits(cross(Vec3(-0.0, 0.0, 1.0), Vec3(0.0, -0.0, 2.0)), Vec3(-0.0, 0.0, 1.0).cross(Vec3(0.0, -0.0, 2.0))));
    CHECK(!cross(Vec3(std::nan(""), 0, 0), Vec3(0, 1, 1)).allFinite());
}
