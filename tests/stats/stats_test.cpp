// Ensemble statistics and the three-outcome verdict: Student t quantiles against printed tables,
// intervals against hand computation, coverage of the 95 % intervals on synthetic draws, and the
// equivalence test on constructed intervals and samples.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "stats/summary.hpp"
#include "stats/verdict.hpp"

using namespace demscale::stats;

TEST_CASE("Student t quantiles match the printed table", "[stats]") {
    // Two-sided 95 %: t(0.975; ν) from any statistics table.
    CHECK(student_t_quantile(0.95, 1) == Approx(12.706).epsilon(1e-4));
    CHECK(student_t_quantile(0.95, 7) == Approx(2.3646).epsilon(1e-4));
    CHECK(student_t_quantile(0.95, 8) == Approx(2.3060).epsilon(1e-4));
    CHECK(student_t_quantile(0.95, 1e7) == Approx(1.95996).epsilon(1e-4));
}

TEST_CASE("Summary of a known sample: mean, sample sd and the t interval by hand", "[stats]") {
    const auto s = summarize({1, 2, 3, 4, 5});
    CHECK(s.n == 5);
    CHECK(s.mean == Approx(3));
    CHECK(s.sd == Approx(std::sqrt(2.5)));
    const double half = 2.7764 * std::sqrt(2.5) / std::sqrt(5.0);  // t(0.975; 4) = 2.7764
    CHECK(s.ci.low == Approx(3 - half).epsilon(1e-4));
    CHECK(s.ci.high == Approx(3 + half).epsilon(1e-4));
    const auto one = summarize({7});
    CHECK(one.sd == 0);
    CHECK(one.ci.low == 7);
    CHECK(one.ci.high == 7);
}

TEST_CASE("Median: the middle value, the upper of two middle ones, 0 for none", "[stats]") {
    CHECK(median({3.0, 1.0, 2.0}) == 2.0);
    CHECK(median({4.0, 1.0, 3.0, 2.0}) == 3.0);
    CHECK(median({}) == 0.0);
}

TEST_CASE("Welch interval: equal sizes and variances give the pooled interval with 2(n - 1) degrees", "[stats]") {
    // a: mean 2, b: mean 5, both with sample variance 2.5 (n = 5): SE = sqrt(2 * 2.5 / 5) = 1, ν = 8.
    const auto d = difference_interval({0, 1, 2, 3, 4}, {3, 4, 5, 6, 7});
    CHECK(d.low == Approx(3 - 2.3060).epsilon(1e-4));
    CHECK(d.high == Approx(3 + 2.3060).epsilon(1e-4));
}

TEST_CASE("95 % intervals cover the true value in about 95 % of trials", "[stats][coverage]") {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> fine(1.0, 2.0), coarse(1.5, 0.5);
    const int trials = 400;
    int mean_covered = 0, difference_covered = 0;
    for (int t = 0; t < trials; ++t) {
        std::vector<double> a(8), b(6);
        for (auto& x : a) x = fine(rng);
        for (auto& x : b) x = coarse(rng);
        mean_covered += summarize(a).ci.contains(1.0);
        difference_covered += difference_interval(a, b).contains(0.5);
    }
    // Binomial(400, 0.95): sd 1.1 %; 0.92-0.98 is about ±2.7 sd.
    INFO("mean " << mean_covered << ", difference " << difference_covered << " of " << trials);
    CHECK(mean_covered >= 0.92 * trials);
    CHECK(mean_covered <= 0.98 * trials);
    CHECK(difference_covered >= 0.92 * trials);
    CHECK(difference_covered <= 0.98 * trials);
}

TEST_CASE("Equivalence verdict: inside PASS, outside FAIL, straddling INCONCLUSIVE", "[stats][verdict]") {
    CHECK(equivalence_verdict({-0.05, 0.05}, 0.1) == Verdict::pass);
    CHECK(equivalence_verdict({0.15, 0.30}, 0.1) == Verdict::fail);
    CHECK(equivalence_verdict({-0.30, -0.20}, 0.1) == Verdict::fail);
    CHECK(equivalence_verdict({0.05, 0.15}, 0.1) == Verdict::inconclusive);
    CHECK(equivalence_verdict({-0.20, 0.20}, 0.1) == Verdict::inconclusive);  // wide: no decision either way
    CHECK(smallest_confirmable_tolerance({-0.02, 0.07}) == Approx(0.07));
    CHECK(smallest_confirmable_tolerance({-0.3, 0.1}) == Approx(0.3));
    CHECK(combine({Verdict::pass, Verdict::pass}) == Verdict::pass);
    CHECK(combine({Verdict::pass, Verdict::inconclusive}) == Verdict::inconclusive);
    CHECK(combine({Verdict::inconclusive, Verdict::fail, Verdict::pass}) == Verdict::fail);
    CHECK(verdict_name(Verdict::inconclusive) == "INCONCLUSIVE");
}

TEST_CASE("Verdicts on constructed samples with known means and spreads", "[stats][verdict]") {
    // Eight values with mean m and sample sd s: m + s * z, z a fixed pattern with mean 0, sd 1.
    const std::vector<double> z = {-1.5, -1.0, -0.5, 0.0, 0.0, 0.5, 1.0, 1.5};
    double z2 = 0;
    for (double x : z) z2 += x * x;
    const double scale = 1 / std::sqrt(z2 / 7);
    auto sample = [&](double m, double s) {
        std::vector<double> v;
        for (double x : z) v.push_back(m + s * scale * x);
        return v;
    };
    const auto fine = sample(0.40, 0.02);
    // Same mean, tight: the interval (± about 0.024) lies inside ±0.05.
    CHECK(equivalence_verdict(difference_interval(fine, sample(0.40, 0.02)), 0.05) == Verdict::pass);
    // 0.2 apart: the interval lies wholly above 0.05.
    CHECK(equivalence_verdict(difference_interval(fine, sample(0.60, 0.02)), 0.05) == Verdict::fail);
    // Same mean but noisy (sd 0.1): the interval (± about 0.08) pokes past ±0.05.
    const auto wide = difference_interval(fine, sample(0.40, 0.10));
    CHECK(equivalence_verdict(wide, 0.05) == Verdict::inconclusive);
    CHECK(smallest_confirmable_tolerance(wide) > 0.05);
    // 0.06 apart with a tight spread straddles 0.05: neither equivalent nor surely different.
    CHECK(equivalence_verdict(difference_interval(fine, sample(0.46, 0.02)), 0.05) == Verdict::inconclusive);
}

TEST_CASE("Verdict: a FAIL counts for a family of m criteria only at 5 % / m (Holm's first step), by hand", "[stats][verdict]") {
    // Slump difference 8 % [6, 10] against ±5 %: FAIL on its own. Widened about 8 by
    // z(1 − 0.025/m)/z(0.975): m = 6, 2.638/1.960 = 1.346, low end 8 − 2·1.346 = 5.31 > 5: still FAIL;
    // m = 20, 3.023/1.960 = 1.542, low end 4.92 < 5: no longer.
    const Interval ci{0.06, 0.10};
    CHECK(fails_in_family(0.08, ci, 0.05, 1));
    CHECK(fails_in_family(0.08, ci, 0.05, 6));
    CHECK_FALSE(fails_in_family(0.08, ci, 0.05, 20));
    CHECK_FALSE(fails_in_family(0.0, {-0.02, 0.02}, 0.05, 1));  // a PASS is no FAIL at any m
    CHECK(fails_in_family(-0.3, {-0.5, -0.17}, 0.05, 6));      // the k = 3 slump at S_f 1.4: far outside
}
