// Synthetic slump runs for tests of the exponent's estimators, in two shapes:
//  - model_form(): the transition model's own form (stats/transition_model.hpp), so that a fit of
//    many runs must give back its parameters: a column stands (slump 0.06 ± 0.03) with probability
//    Φ((u − ln 0.15)/0.25); where P(stand) ≥ 0.1 a column that fails collapses to 0.535 ± 0.03;
//    elsewhere it follows y = 0.521 − 0.197 v + 0.032 v² with sd 0.015; sd the same at every S_f.
//  - reference_measured(): the reference scene's runs (data/scenes/kantro_wet.toml, 12 seeds per
//    level, seed bases 101, 201 and 301, measured 2026-12-07; docs/exponent-checks.md). No column
//    stood: the slump falls on a concave branch, the cubic through the fine means and the coarse
//    ones read at k = 1 after their dry offsets, y = 0.526 − 0.353 v − 0.273 v² − 0.075 v³
//    (residuals ≤ 0.014), and its run-to-run sd grows towards the transition and with S_f:
//    0.0055 e^{1.2 (v + ln 2)} S_f^1.5 (measured fine 0.005-0.019, S_f 1.4 0.008-0.028,
//    1.96 0.019-0.035); a level whose own γ exceeds 0.17 N/m is lost (S_f 1.96's fills fall short).
// In both, u = ln γ − k ln S_f and v = u − ln 0.074 (a coarse run at γ̄ behaves like a fine run at
// γ̄ / S_f^k); the dry control slumps 0.763 fine and more coarse (the dry offset).
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "stats/curve_shift.hpp"

namespace demscale::test {

struct RunShape {
    std::vector<double> branch;    // y(v) = Σ branch[j] vʲ
    double sd = 0.015;             // run-to-run sd on the branch at v = −ln 2 (γ/2), fine
    double sd_growth = 0;          // d ln sd / dv
    double sd_sf_power = 0;        // sd ∝ S_f^this
    bool stands = false;           // the model's form: standing columns and collapses near them
    double dry_offset_196 = 0.027; // coarse dry control above the fine one at S_f 1.96 (∝ ln S_f)
    double dry_sd = 0.005;         // fine
    double dry_sd_sf_power = 0;    // the dry sd ∝ S_f^this
    double lost_above = 0.27;      // N/m: a level whose own γ exceeds it is lost
};

inline RunShape model_form() { return {{0.521, -0.197, 0.032}, 0.015, 0, 0, true, 0.027, 0.005, 0, 0.27}; }
inline RunShape reference_measured() { return {{0.526, -0.353, -0.273, -0.075}, 0.0055, 1.2, 1.5, false, 0.017, 0.0053, 0.8, 0.17}; }

// estimate-exponent's default design (the shipped design before 2026-12-07 was 0.5, 1, 2, 4 with
// offset 2 and 8 seeds).
struct ReferenceLikeDesign {
    std::vector<double> factors = {0.5, 0.669, 0.894, 1.196, 1.6};
    std::vector<double> sfs = {1.4, 1.96};
    double offset = 1;
    int seeds = 4;
    bool control = true;
    RunShape shape = reference_measured();
};

inline double shape_branch(const RunShape& s, double u) {
    const double v = u - std::log(0.074);
    double y = 0, power = 1;
    for (double c : s.branch) y += c * power, power *= v;
    return y;
}
inline double model_stand_probability(double u) { return 0.5 * std::erfc(-(u - std::log(0.15)) / 0.25 / std::sqrt(2.0)); }

inline double shape_dry_offset(const RunShape& s, double sf) { return sf <= 1 ? 0.0 : s.dry_offset_196 * std::log(sf) / std::log(1.96); }

// One run's slump over fill height at the run's own ln γ (coarse at S_f with true exponent k).
inline double shaped_run(const RunShape& s, double x, double sf, double k, std::mt19937_64& rng) {
    const double u = x - k * std::log(sf);
    std::uniform_real_distribution<double> coin(0, 1);
    std::normal_distribution<double> noise(0, 1);
    const double offset = shape_dry_offset(s, sf);
    if (s.stands) {
        const double p = model_stand_probability(u);
        if (coin(rng) < p) return std::max(0.0, 0.06 + 0.03 * noise(rng));
        if (p >= 0.1) return 0.535 + offset + 0.03 * noise(rng);
    }
    const double sd = s.sd * std::exp(s.sd_growth * (u - std::log(0.037))) * std::pow(sf, s.sd_sf_power);
    return std::max(0.0, shape_branch(s, u) + offset + sd * noise(rng));  // a pile does not rise
}

inline stats::ResponseCurve reference_like_curve(double sf, double k, const ReferenceLikeDesign& d, std::mt19937_64& rng) {
    stats::ResponseCurve c;
    c.sf = sf;
    const double gamma = 0.074;
    for (double f : d.factors) {
        const double g = f * gamma * (sf > 1 ? std::pow(sf, d.offset) : 1.0);
        if (g > d.shape.lost_above) continue;  // the fill falls short: the level is lost
        stats::ResponseLevel l;
        l.x = std::log(g);
        for (int s = 0; s < d.seeds; ++s) l.y.push_back(shaped_run(d.shape, l.x, sf, k, rng)), l.seed.push_back(s);
        c.levels.push_back(l);
    }
    if (d.control) {
        const double sd = d.shape.dry_sd * std::pow(sf, d.shape.dry_sd_sf_power);
        std::normal_distribution<double> noise(0, sd);
        for (int s = 0; s < d.seeds; ++s) c.control.y.push_back(0.763 + shape_dry_offset(d.shape, sf) + noise(rng)), c.control.seed.push_back(s);
    }
    return c;
}

}  // namespace demscale::test
