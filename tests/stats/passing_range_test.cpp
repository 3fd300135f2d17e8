// The range of k that passes (stats/passing_range.hpp), against a straight branch by hand.
#include <catch2/catch.hpp>
#include <cmath>

#include "stats/passing_range.hpp"

using namespace demscale::stats;

namespace {
// A fit with the straight branch y = 0.5 − 0.2 (u − ln 0.1), nothing standing, k̂ = 1 [0.9, 1.2].
TransitionFit straight() {
    TransitionFit f;
    f.k = 1, f.ci = {0.9, 1.2};
    f.centre = std::log(0.1), f.branch = {0.5, -0.2};
    f.threshold = NAN, f.slumped = 10;
    return f;
}
}  // namespace

TEST_CASE("Passing range: a straight branch gives k-hat plus or minus tolerance over slope times ln S_f", "[stats][exponent]") {
    // |Δ| = 0.2 |δ| ln 2 ≤ 0.05  ⇔  |δ| ≤ 0.05 / (0.2 ln 2) = 0.3607 (by hand).
    const double band = 0.05 / (0.2 * std::log(2.0));
    const auto r = passing_range(straight(), 2, std::log(0.1), 0.05, {std::log(0.02), std::log(0.5)});
    CHECK(r.at_k_hat.low == Approx(1 - band).margin(0.006));
    CHECK(r.at_k_hat.high == Approx(1 + band).margin(0.006));
    CHECK(r.over_interval.low == Approx(1.2 - band).margin(0.006));  // every k* in [0.9, 1.2] must pass
    CHECK(r.over_interval.high == Approx(0.9 + band).margin(0.006));
    CHECK_FALSE(r.low_open);
    CHECK_FALSE(r.empty());
    // k̂'s interval wider than the band: nothing passes for every k* in it.
    TransitionFit wide = straight();
    wide.ci = {0.5, 1.5};
    CHECK(passing_range(wide, 2, std::log(0.1), 0.05, {std::log(0.02), std::log(0.5)}).empty());
}

TEST_CASE("Passing range: where the fine levels end first, that end is open", "[stats][exponent]") {
    // Fine levels only up to γ = 0.12: the band (δ ln 2 ≤ 0.25) would reach 0.128, past them.
    const auto r = passing_range(straight(), 2, std::log(0.1), 0.05, {std::log(0.02), std::log(0.12)});
    CHECK(r.high_open);
    CHECK_FALSE(r.low_open);
    CHECK(r.at_k_hat.high == Approx(1 + std::log(1.2) / std::log(2.0)).margin(0.006));
    // Jointly: the intersection of the S_f's ranges from the joint fit (the last one).
    const auto all = passing_ranges({straight(), straight(), straight()}, {2, 4}, std::log(0.1), 0.05, {std::log(0.02), std::log(0.5)});
    REQUIRE(all.size() == 3);
    CHECK(all[2].sf == 0);
    const double band4 = 0.05 / (0.2 * std::log(4.0));  // the larger S_f's narrower band decides
    CHECK(all[2].at_k_hat.low == Approx(1 - band4).margin(0.006));
    CHECK(all[2].at_k_hat.high == Approx(1 + band4).margin(0.006));
}
