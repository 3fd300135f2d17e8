// Synthetic slump runs shaped like the reference scene's (data/scenes/kantro_wet.toml, 8 seeds,
// measured 2026-12-07; docs/exponent-checks.md), for coverage tests of the exponent's intervals:
//  - a column stands with probability Φ((u − θ)/w), θ = ln 0.15 N/m, w = 0.25 (fine at 0.148 N/m:
//    4 of 8 seeds stood; at 0.074 none; fine and coarse alike in u = ln γ − k ln S_f);
//  - a standing column slumps 0.06 ± 0.03 of its height; a slumped one follows the branch through the
//    fine means 0.673 (γ = 0.037), 0.521 (0.074) and S_f 1.4's 0.40 at 0.145 N/m read at k = 1,
//    y = 0.521 − 0.197 v + 0.032 v², v = u − ln 0.074, with a run-to-run sd of 0.015; but where
//    P(stand) ≥ 0.1 a column that fails collapses: 0.535 ± 0.03 (the fine runs that slumped at 2γ);
//  - the dry control slumps 0.763 ± 0.005 fine, and 0.009 (S_f 1.4) and 0.027 (1.96) more coarse;
//  - a level whose own γ exceeds 0.27 N/m is lost (the cone's fills fall short there);
//  - the design: fine levels f·γ, coarse f·γ·S_f^offset, γ = 0.074 N/m.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "stats/curve_shift.hpp"

namespace demscale::test {

// estimate-exponent's default design (the shipped design before 2026-12-07 was 0.5, 1, 2, 4 with
// offset 2 and 8 seeds).
struct ReferenceLikeDesign {
    std::vector<double> factors = {0.5, 0.669, 0.894, 1.196, 1.6};
    std::vector<double> sfs = {1.4, 1.96};
    double offset = 1;
    int seeds = 4;
    bool control = true;
};

inline double reference_branch(double u) {
    const double v = u - std::log(0.074);
    return 0.521 - 0.197 * v + 0.032 * v * v;
}
inline double reference_stand_probability(double u) { return 0.5 * std::erfc(-(u - std::log(0.15)) / 0.25 / std::sqrt(2.0)); }

inline double reference_dry_offset(double sf) { return sf <= 1 ? 0.0 : 0.027 * std::log(sf) / std::log(1.96); }

// One run's slump over fill height at the run's own ln γ (coarse at S_f with true exponent k).
inline double reference_like_run(double x, double sf, double k, std::mt19937_64& rng) {
    const double u = x - k * std::log(sf);
    std::uniform_real_distribution<double> coin(0, 1);
    std::normal_distribution<double> noise(0, 1);
    const double p = reference_stand_probability(u);
    if (coin(rng) < p) return std::max(0.0, 0.06 + 0.03 * noise(rng));
    if (p >= 0.1) return 0.535 + reference_dry_offset(sf) + 0.03 * noise(rng);
    return reference_branch(u) + reference_dry_offset(sf) + 0.015 * noise(rng);
}

inline stats::ResponseCurve reference_like_curve(double sf, double k, const ReferenceLikeDesign& d, std::mt19937_64& rng) {
    stats::ResponseCurve c;
    c.sf = sf;
    const double gamma = 0.074;
    for (double f : d.factors) {
        const double g = f * gamma * (sf > 1 ? std::pow(sf, d.offset) : 1.0);
        if (g > 0.27) continue;  // the fill falls short: the level is lost
        stats::ResponseLevel l;
        l.x = std::log(g);
        for (int s = 0; s < d.seeds; ++s) l.y.push_back(reference_like_run(l.x, sf, k, rng)), l.seed.push_back(s);
        c.levels.push_back(l);
    }
    if (d.control) {
        std::normal_distribution<double> noise(0, 0.005);
        for (int s = 0; s < d.seeds; ++s) c.control.y.push_back(0.763 + reference_dry_offset(sf) + noise(rng)), c.control.seed.push_back(s);
    }
    return c;
}

}  // namespace demscale::test
