// The exponent estimator on synthetic response curves with a known shift: it recovers k inside
// its interval, its 95 % interval covers the true k in roughly 95 % of a few hundred trials, a
// curve that only touches the plateaus is reported as undetermined, and the interpolant is checked
// against the points it passes through.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "stats/curve_shift.hpp"

using namespace demscale::stats;

namespace {

// A slump-like response: 0.8 of the height slumps with no cohesion, nothing with much of it;
// the transition at γ = 0.1 N/m, about one factor e wide.
double true_response(double log_gamma) { return 0.8 / (1 + std::exp((log_gamma - std::log(0.1)) / 0.35)); }

// Levels at γ₀·2^i, i = 0 … levels − 1, with `seeds` noisy runs each; a coarse curve at S_f with
// exponent k is the fine response at ln γ̄ − k ln S_f (what particle replacement with the right k gives).
ResponseCurve synthetic(double sf, double k, double gamma0, int levels, int seeds, double noise, std::mt19937_64& rng) {
    std::normal_distribution<double> n(0, noise);
    ResponseCurve c;
    c.sf = sf;
    for (int i = 0; i < levels; ++i) {
        ResponseLevel l;
        l.x = std::log(gamma0) + i * std::log(2.0);
        for (int s = 0; s < seeds; ++s) l.y.push_back(true_response(l.x - k * std::log(sf)) + n(rng));
        c.levels.push_back(l);
    }
    return c;
}

}  // namespace

TEST_CASE("Curve shift: the interpolant passes through the means and is flat beyond them", "[stats][exponent]") {
    ResponseCurve f;
    f.levels = {{0.0, {0.8, 0.6}, {}}, {1.0, {0.5}, {}}, {2.0, {0.1, 0.3}, {}}};
    CHECK(interpolate_response(f, 0.0) == Approx(0.7));
    CHECK(interpolate_response(f, 1.0) == Approx(0.5));
    CHECK(interpolate_response(f, 2.0) == Approx(0.2));
    CHECK(interpolate_response(f, -5.0) == Approx(0.7));
    CHECK(interpolate_response(f, 9.0) == Approx(0.2));
    const double mid = interpolate_response(f, 1.5);
    CHECK(mid < 0.5);
    CHECK(mid > 0.2);  // monotone between monotone means (Steffen)
}

TEST_CASE("Curve shift: noiseless curves give back the exponent they were made with", "[stats][exponent]") {
    std::mt19937_64 rng(1);
    for (double k_true : {1.0, 2.0, 3.0}) {
        INFO("k = " << k_true);
        // Coarse levels start at γ₀ S_f² (the Bond-number guess), as the command places them.
        const ResponseCurve fine = synthetic(1, 0, 0.025, 6, 4, 0.0, rng);
        const ResponseCurve c14 = synthetic(1.4, k_true, 0.025 * 1.96, 6, 4, 0.0, rng);
        const ResponseCurve c196 = synthetic(1.96, k_true, 0.025 * 1.96 * 1.96, 6, 4, 0.0, rng);
        const auto e = estimate_exponent(fine, {c14, c196}, {-2, 6, 50, 1});
        REQUIRE(e.size() == 3);  // per S_f, then joint
        CHECK(e[0].sf == 1.4);
        CHECK(e[2].sf == 0);
        for (const auto& one : e) {
            CHECK(one.k == Approx(k_true).margin(0.12));  // only the interpolant's error
            CHECK(one.determined);
        }
        CHECK(e[2].rms < shift_residual_rms(fine, {c14, c196}, k_true + 1));
    }
}

TEST_CASE("Curve shift: a control offset is subtracted, not read as a shift in k", "[stats][exponent]") {
    std::mt19937_64 rng(2);
    // The coarse piles slump 0.05 of the height more at every cohesion, as their dry control does:
    // raw, that offset pulls k-hat off; with the controls it is subtracted and k = 1 comes back.
    const double k_true = 1, offset = 0.05;
    const ResponseCurve fine = synthetic(1, 0, 0.025, 6, 4, 0.0, rng);
    ResponseCurve coarse = synthetic(1.4, k_true, 0.025 * 1.96, 6, 4, 0.0, rng);
    for (auto& l : coarse.levels)
        for (auto& y : l.y) y += offset;
    const auto raw = estimate_exponent(fine, {coarse}, {-2, 6, 50, 1});
    CHECK(std::abs(raw[0].k - k_true) > 0.3);
    CHECK(raw[0].offset == 0.0);
    ResponseCurve fine_c = fine, coarse_c = coarse;
    fine_c.control.y = {0.78, 0.80, 0.82};
    coarse_c.control.y = {0.83, 0.85, 0.87};
    CHECK(control_offset(fine_c, coarse_c) == Approx(offset));
    CHECK(control_offset(fine, coarse_c) == 0.0);  // a control on one side only is no control
    const auto corrected = estimate_exponent(fine_c, {coarse_c}, {-2, 6, 200, 1});
    CHECK(corrected[0].k == Approx(k_true).margin(0.12));
    CHECK(corrected[0].offset == Approx(offset));
    CHECK(corrected[0].ci.contains(k_true));
    CHECK(shift_residual_rms(fine_c, {coarse_c}, k_true) < 0.01);
    CHECK(shift_residual_rms(fine, {coarse}, k_true) == Approx(offset).epsilon(0.05));
}

TEST_CASE("Curve shift: the 95 % interval covers the true exponent in about 95 % of trials", "[stats][exponent]") {
    std::mt19937_64 rng(7);
    const double k_true = 1.0;
    int covered = 0, determined = 0, inside_own = 0;
    const int trials = 300;
    for (int t = 0; t < trials; ++t) {
        const ResponseCurve fine = synthetic(1, 0, 0.025, 6, 8, 0.03, rng);
        const ResponseCurve coarse = synthetic(1.96, k_true, 0.025 * 1.96 * 1.96, 6, 8, 0.03, rng);
        const auto e = estimate_exponent(fine, {coarse}, {-2, 6, 200, static_cast<unsigned>(t + 1)});
        REQUIRE(e.size() == 1);
        covered += e[0].ci.contains(k_true);
        determined += e[0].determined;
        inside_own += e[0].ci.contains(e[0].k);
    }
    INFO(covered << " of " << trials << " intervals cover k = 1");
    CHECK(covered >= static_cast<int>(0.88 * trials));
    CHECK(covered <= static_cast<int>(0.99 * trials));
    CHECK(determined == trials);
    CHECK(inside_own == trials);
}

TEST_CASE("Curve shift: coarse levels on the plateaus do not determine the exponent", "[stats][exponent]") {
    std::mt19937_64 rng(3);
    const ResponseCurve fine = synthetic(1, 0, 0.025, 6, 8, 0.03, rng);
    // Every coarse level far into the standing plateau: any shift that keeps them there fits.
    const ResponseCurve coarse = synthetic(1.4, 1.0, 40.0, 3, 8, 0.03, rng);
    const auto e = estimate_exponent(fine, {coarse}, {-2, 6, 200, 1});
    CHECK_FALSE(e[0].determined);
}

TEST_CASE("Curve shift: bad curves are refused", "[stats][exponent]") {
    ResponseCurve fine, coarse;
    fine.levels = {{0.0, {0.5}, {}}};
    coarse.sf = 1.4;
    coarse.levels = {{0.0, {0.5}, {}}};
    CHECK_THROWS_AS(estimate_exponent(fine, {coarse}), std::invalid_argument);  // one fine level
    fine.levels.push_back({1.0, {}, {}});
    CHECK_THROWS_AS(estimate_exponent(fine, {coarse}), std::invalid_argument);  // a level without runs
    fine.levels.back().y = {0.4};
    coarse.sf = 1.0;
    CHECK_THROWS_AS(estimate_exponent(fine, {coarse}), std::invalid_argument);  // S_f = 1
}

TEST_CASE("Curve shift: a level whose seeds stood and slumped is named, and the estimates resting on it say so", "[stats][exponent]") {
    // Level means span 0.01 (fine, high γ) to 0.70 (fine, low γ): thirds at 0.24 and 0.47 (by hand).
    ResponseCurve fine;
    fine.levels = {{0.0, {0.69, 0.71}, {}}, {1.0, {0.50, 0.56, 0.53}, {}}, {2.0, {0.02, 0.60, 0.03, 0.01}, {}}, {3.0, {0.01, 0.01}, {}}};
    ResponseCurve coarse14, coarse2;
    coarse14.sf = 1.4, coarse2.sf = 2;
    coarse14.levels = {{0.5, {0.60, 0.62}, {}}, {1.5, {0.30, 0.35}, {}}, {2.5, {0.02, 0.02}, {}}};  // 0.30-0.35: middle third, not split
    coarse2.levels = {{1.0, {0.65, 0.66}, {}}, {2.0, {0.20, 0.50, 0.22}, {}}, {3.0, {0.01, 0.02}, {}}};  // 0.20 and 0.22 low, 0.50 high
    const auto split = split_levels(fine, {coarse14, coarse2});
    REQUIRE(split.size() == 2);
    CHECK(split[0].sf == 1);
    CHECK(split[0].x == 2.0);
    CHECK(split[0].low == 3);   // 0.02, 0.03, 0.01 ≤ 0.24
    CHECK(split[0].high == 1);  // 0.60 ≥ 0.47
    CHECK(split[0].seeds == 4);
    CHECK(split[1].sf == 2);
    CHECK(split[1].x == 2.0);
    CHECK(split[1].low == 2);   // 0.20, 0.22
    CHECK(split[1].high == 1);  // 0.50

    ShiftSearch search;
    search.resamples = 50;
    const auto e = estimate_exponent(fine, {coarse14, coarse2}, search);
    REQUIRE(e.size() == 3);
    CHECK(e[0].split_levels == 1);  // S_f 1.4: the fine level only
    CHECK(e[1].split_levels == 2);  // S_f 2: the fine level and its own
    CHECK(e[2].split_levels == 2);  // jointly: both

    // Seeds that agree split nothing; nor does a flat response.
    ResponseCurve steady = fine;
    steady.levels[2].y = {0.02, 0.03, 0.03, 0.01};
    coarse2.levels[1].y = {0.30, 0.35, 0.32};
    CHECK(split_levels(steady, {coarse14, coarse2}).empty());
    ResponseCurve flat;
    flat.levels = {{0.0, {0.1, 0.1}, {}}, {1.0, {0.1, 0.1}, {}}};
    CHECK(split_levels(flat, {}).empty());
}
