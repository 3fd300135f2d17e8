// The transition model of the exponent (stats/transition_model.hpp): it gives back the parameters
// synthetic runs were drawn with, an offset measured by the controls is not read as k, and its
// 95 % interval covers the true k in 90-99.5 % of 200 draws of runs shaped like the reference
// scene's measured ones (tests/stats/reference_like_runs.hpp), for k = 0.5, 1 and 1.5; at k = 2 it
// says the default design's coarse levels are extrapolated, and a design moved there covers.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "reference_like_runs.hpp"
#include "stats/transition_model.hpp"

using namespace demscale;
using namespace demscale::stats;

TEST_CASE("Transition model: many runs give back the threshold, its width, the branch and k", "[stats][exponent]") {
    std::mt19937_64 rng(11);
    test::ReferenceLikeDesign d;
    d.factors = {0.4, 0.5, 0.63, 0.8, 1, 1.26, 1.59, 2, 2.52, 3.17};
    d.offset = 1, d.seeds = 300, d.shape = test::model_form();
    const double k_true = 1.3;
    const ResponseCurve fine = test::reference_like_curve(1, 0, d, rng);
    const ResponseCurve coarse = test::reference_like_curve(1.96, k_true, d, rng);
    const auto fit = fit_transition(fine, {coarse});
    REQUIRE(fit.size() == 1);
    CHECK(fit[0].quantal);
    CHECK(fit[0].k == Approx(k_true).margin(0.03));
    CHECK(fit[0].ci.contains(k_true));
    CHECK(fit[0].ci.high - fit[0].ci.low < 0.1);
    CHECK(fit[0].threshold == Approx(std::log(0.15)).margin(0.04));
    CHECK(fit[0].width == Approx(0.25).margin(0.05));
    CHECK(fit[0].sigma == Approx(0.015).margin(0.002));
    CHECK(fit[0].offsets.at(0) == Approx(test::shape_dry_offset(d.shape, 1.96)).margin(0.002));
    for (double g : {0.03, 0.06, 0.1, 0.14}) CHECK(slumped_branch(fit[0], std::log(g)) == Approx(test::shape_branch(d.shape, std::log(g))).margin(0.006));
    CHECK(stand_probability(fit[0], std::log(0.15)) == Approx(0.5).margin(0.06));
    CHECK(mean_response(fit[0], std::log(0.01)) == Approx(slumped_branch(fit[0], std::log(0.01))).margin(1e-6));  // nothing stands there
}

TEST_CASE("Transition model: a profile narrower than the search grid gives the same interval wherever the grid falls",
          "[stats][exponent]") {
    // 40 seeds a level: the 95 % profile interval is about 0.05 wide, half the grid step of 0.1. Its
    // ends are where the deviance crosses the cutoff, which does not depend on the grid; the grid
    // point nearest k̂ can lie outside the interval already, and an interval grown from it ended at
    // that grid point. Moving the grid by half a step (k_min -2 against -2.05) must not move it.
    std::mt19937_64 rng(23);
    test::ReferenceLikeDesign d;
    d.seeds = 40, d.shape = test::model_form(), d.control = false;
    const ResponseCurve fine = test::reference_like_curve(1, 0, d, rng);
    const ResponseCurve coarse = test::reference_like_curve(1.96, 0.97, d, rng);
    int narrower_than_grid = 0;
    for (double k_min : {-2.03, -2.05, -2.07}) {  // the grid moved by 0.03, 0.05 and 0.07
        TransitionSettings s;
        s.k_min = k_min;
        const auto a = fit_transition(fine, {coarse}).at(0), b = fit_transition(fine, {coarse}, s).at(0);
        REQUIRE(a.profile_ci.contains(a.k));
        CHECK(b.k == Approx(a.k).margin(1e-6));
        CHECK(b.profile_ci.low == Approx(a.profile_ci.low).margin(1e-6));
        CHECK(b.profile_ci.high == Approx(a.profile_ci.high).margin(1e-6));
        narrower_than_grid += a.profile_ci.high - a.profile_ci.low < 0.1;
    }
    CHECK(narrower_than_grid == 3);  // the case the test is for
}

TEST_CASE("Transition model: without standing runs it is the shift of the slumped branch, by hand", "[stats][exponent]") {
    // A straight branch y = 0.5 − 0.2 (u − ln 0.1) and no noise: the coarse levels at γ̄ = 0.2 and
    // 0.4 N/m with S_f = 2, k = 1 lie where the fine one has 0.1 and 0.2: y = 0.5 and 0.5 − 0.2 ln 2.
    auto y = [](double u) { return 0.5 - 0.2 * (u - std::log(0.1)); };
    ResponseCurve fine, coarse;
    for (double g : {0.05, 0.1, 0.2}) fine.levels.push_back({std::log(g), {y(std::log(g)), y(std::log(g))}, {}});
    coarse.sf = 2;
    for (double g : {0.2, 0.4}) coarse.levels.push_back({std::log(g), {y(std::log(g / 2)), y(std::log(g / 2))}, {}});
    const auto fit = fit_transition(fine, {coarse});
    CHECK_FALSE(fit[0].quantal);
    CHECK(fit[0].standing == 0);
    CHECK(fit[0].k == Approx(1).margin(1e-3));
    CHECK(fit[0].ci.high - fit[0].ci.low < 0.01);
    // Moved up by a dry offset of 0.03 that the controls measure: still k = 1, and the offset found.
    for (auto& l : coarse.levels)
        for (auto& v : l.y) v += 0.03;
    const auto raw = fit_transition(fine, {coarse});
    CHECK(raw[0].k == Approx(1 + 0.03 / (0.2 * std::log(2.0))).margin(2e-3));  // the offset read as a shift
    fine.control.y = {0.80, 0.81, 0.79};
    coarse.control.y = {0.83, 0.84, 0.82};
    const auto corrected = fit_transition(fine, {coarse});
    CHECK(corrected[0].k == Approx(1).margin(2e-3));
    CHECK(corrected[0].offsets.at(0) == Approx(0.03).margin(1e-6));
}

namespace {

struct Coverage {
    int covered[3] = {0, 0, 0}, extrapolated[3] = {0, 0, 0}, profile_covered[3] = {0, 0, 0};
    double joint_width = 0, jackknife_variance = 0, squared_error = 0;  // joint, over the draws judged
    int judged(int i, int draws) const { return draws - extrapolated[i]; }
};

// Draws of the reference scene's measured runs (tests/stats/reference_like_runs.hpp) on a design, the
// model fitted to each; an interval flagged extrapolated is not judged (the command says so).
Coverage coverage(double k_true, const test::ReferenceLikeDesign& d, int draws) {
    Coverage c;
    for (int t = 0; t < draws; ++t) {
        std::mt19937_64 rng(static_cast<unsigned>(1000 * k_true) + static_cast<unsigned>(t));
        const ResponseCurve fine = test::reference_like_curve(1, 0, d, rng);
        std::vector<ResponseCurve> coarse;
        for (double sf : d.sfs) coarse.push_back(test::reference_like_curve(sf, k_true, d, rng));
        const auto fit = fit_transition(fine, coarse);
        REQUIRE(fit.size() == 3);
        for (std::size_t i = 0; i < 3; ++i) {
            if (fit[i].extrapolated) {
                c.extrapolated[i]++;
                continue;
            }
            c.covered[i] += fit[i].ci.contains(k_true);
            c.profile_covered[i] += fit[i].profile_ci.contains(k_true);
        }
        if (!fit[2].extrapolated) {
            c.joint_width += fit[2].ci.high - fit[2].ci.low;
            c.jackknife_variance += fit[2].jackknife_se * fit[2].jackknife_se;
            c.squared_error += (fit[2].k - k_true) * (fit[2].k - k_true);
        }
    }
    const int n = std::max(1, c.judged(2, draws));
    c.joint_width /= n, c.jackknife_variance /= n, c.squared_error /= n;
    return c;
}

}  // namespace

TEST_CASE("Transition model: the 95 % interval covers the true k on reference-like runs", "[stats][exponent][coverage][slow]") {
    // estimate-exponent's default design (fine 0.5-1.6 γ in 5 levels, coarse at f γ S_f, 4 seeds, the
    // dry control), on runs shaped like the reference scene's measured ones: a widening branch, its
    // sd growing towards the transition and with S_f. 200 draws per true k, generator seeds 1000 k + draw.
    const int draws = 200;
    for (double k_true : {0.5, 1.0}) {
        const Coverage c = coverage(k_true, test::ReferenceLikeDesign{}, draws);
        WARN("k = " << k_true << ": covered " << c.covered[0] << ", " << c.covered[1] << ", " << c.covered[2] << " (profile alone "
                    << c.profile_covered[0] << ", " << c.profile_covered[1] << ", " << c.profile_covered[2] << ") of " << c.judged(0, draws)
                    << ", " << c.judged(1, draws) << ", " << c.judged(2, draws) << " not extrapolated (S_f 1.4, 1.96, joint); mean joint width "
                    << c.joint_width << "; jackknife variance " << c.jackknife_variance << " against the squared error " << c.squared_error);
        for (int i = 0; i < 3; ++i) {
            CHECK(c.judged(i, draws) >= static_cast<int>(0.95 * draws));  // inside the design's reach
            CHECK(c.covered[i] >= static_cast<int>(0.90 * c.judged(i, draws)));
            CHECK(c.covered[i] <= static_cast<int>(0.995 * c.judged(i, draws)));
        }
        // A second method for the jackknife: its mean variance against the draws' own squared error.
        CHECK(c.jackknife_variance > 0.6 * c.squared_error);
        CHECK(c.jackknife_variance < 2.0 * c.squared_error);
    }
}

TEST_CASE("Transition model: beyond the design's reach it says extrapolated", "[stats][exponent][coverage][slow]") {
    // The default design reaches k of about 0.35-1.2 at S_f 1.96 (docs/exponent-estimate.md): at
    // k = 1.5 and 2 its usable coarse levels (γ̄ ≤ 0.17 N/m) sit at 0.26-0.64 γ in fine terms, partly
    // below every fine level, where the branch is an extrapolated polynomial, and the fit must say
    // so (moving them with --offset is no cure on this scene: the cone's fills fall short above
    // 0.17 N/m). S_f 1.4's levels still overlap the fine ones, and still cover.
    const int draws = 200;
    for (double k_true : {1.5, 2.0}) {
        const Coverage c = coverage(k_true, test::ReferenceLikeDesign{}, draws);
        WARN("k = " << k_true << ": extrapolated " << c.extrapolated[0] << ", " << c.extrapolated[1] << ", " << c.extrapolated[2] << " of "
                    << draws << "; S_f 1.4 covered " << c.covered[0] << " of " << c.judged(0, draws));
        CHECK(c.extrapolated[1] >= static_cast<int>(0.8 * draws));
        CHECK(c.extrapolated[2] >= static_cast<int>(0.8 * draws));
        CHECK(c.judged(0, draws) >= static_cast<int>(0.95 * draws));
        CHECK(c.covered[0] >= static_cast<int>(0.90 * c.judged(0, draws)));
    }
}

TEST_CASE("Transition model: the means-shift bootstrap it replaces does not cover on the same runs", "[stats][exponent][coverage][slow]") {
    // Why the model decides (docs/exponent-estimate.md): on draws of the model's form, the shift of the level
    // means with its seed bootstrap (stats/curve_shift.hpp, 200 resamples) covers far less than 95 %
    // for some k (measured 2026-12-07: 54-93 % over k = 0.5-2 and S_f 1.4, 1.96, joint).
    const int draws = 200;
    int worst = draws;
    for (double k_true : {0.5, 1.0, 1.5, 2.0}) {
        int covered[3] = {0, 0, 0};
        for (int t = 0; t < draws; ++t) {
            std::mt19937_64 rng(static_cast<unsigned>(1000 * k_true) + static_cast<unsigned>(t));
            test::ReferenceLikeDesign d;
            d.factors = {0.5, 1, 2, 4}, d.offset = 2, d.seeds = 8;  // the design it was shipped with
            d.shape = test::model_form();                          // and the runs it was measured on
            const ResponseCurve fine = test::reference_like_curve(1, 0, d, rng);
            std::vector<ResponseCurve> coarse;
            for (double sf : d.sfs) coarse.push_back(test::reference_like_curve(sf, k_true, d, rng));
            const auto e = estimate_exponent(fine, coarse, {-2, 6, 200, static_cast<unsigned>(t + 1)});
            for (int i = 0; i < 3; ++i) covered[i] += e[static_cast<std::size_t>(i)].ci.contains(k_true);
        }
        WARN("means shift, k = " << k_true << ": covered " << covered[0] << ", " << covered[1] << ", " << covered[2] << " of " << draws);
        for (int c : covered) worst = std::min(worst, c);
    }
    CHECK(worst < static_cast<int>(0.85 * draws));
}

