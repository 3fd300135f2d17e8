#include "stats/shape_distance.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace demscale::stats {

namespace {

std::vector<double> mean_of(const std::vector<std::vector<double>>& shapes, const std::vector<std::size_t>& pick) {
    std::vector<double> m(shapes.front().size(), 0.0);
    for (std::size_t i : pick)
        for (std::size_t j = 0; j < m.size(); ++j) m[j] += shapes[i][j] / static_cast<double>(pick.size());
    return m;
}

// S / n: the mean shape's expected squared noise, S = Σ ‖x_i − x̄‖² / (n − 1).
double noise_of_mean(const std::vector<std::vector<double>>& shapes, const std::vector<std::size_t>& pick, const std::vector<double>& mean) {
    if (pick.size() < 2) return 0.0;
    double s = 0;
    for (std::size_t i : pick)
        for (std::size_t j = 0; j < mean.size(); ++j) s += (shapes[i][j] - mean[j]) * (shapes[i][j] - mean[j]);
    const double n = static_cast<double>(pick.size());
    return s / (n - 1) / n;
}

std::vector<std::size_t> every(std::size_t n) {
    std::vector<std::size_t> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

// D² over the norm² (corrected: the noise terms subtracted, so it may be negative).
double squared_distance(const ShapeEnsembles& s, const std::vector<std::size_t>& ci, const std::vector<std::size_t>& fi, bool corrected) {
    const auto c = mean_of(s.coarse, ci), f = mean_of(s.fine, fi), n = mean_of(s.norm, fi);
    double d2 = 0, n2 = 0;
    for (std::size_t j = 0; j < c.size(); ++j) d2 += (c[j] - f[j]) * (c[j] - f[j]), n2 += n[j] * n[j];
    if (corrected) d2 -= noise_of_mean(s.coarse, ci, c) + noise_of_mean(s.fine, fi, f);
    return n2 > 0 ? d2 / n2 : 0.0;
}

}  // namespace

double shape_distance_of(const ShapeEnsembles& s, const std::vector<std::size_t>& ci, const std::vector<std::size_t>& fi, bool corrected) {
    return std::sqrt(std::max(0.0, squared_distance(s, ci, fi, corrected)));
}

ShapeDistance measure_shape_distance(const ShapeEnsembles& s, int resamples, unsigned seed) {
    ShapeDistance r;
    const auto all_c = every(s.coarse.size()), all_f = every(s.fine.size());
    const double d2 = squared_distance(s, all_c, all_f, true);
    r.distance = std::sqrt(std::max(0.0, d2));
    r.plain = shape_distance_of(s, all_c, all_f, false);
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::size_t> pick_f(0, s.fine.size() - 1), pick_c(0, s.coarse.size() - 1);
    std::vector<double> d;
    std::vector<std::size_t> fi(s.fine.size()), ci(s.coarse.size());
    for (int b = 0; b < resamples; ++b) {
        for (auto& i : fi) i = pick_f(rng);
        for (auto& i : ci) i = pick_c(rng);
        d.push_back(squared_distance(s, ci, fi, true));
    }
    // Normal interval on D² with the bootstrap's sd (D² is near normal where D is not: it is a sum of
    // squares less a noise term, and its square root is skewed and cut at 0), then its square root.
    const double sd = summarize(d).sd;
    r.ci = {std::sqrt(std::max(0.0, d2 - 1.96 * sd)), std::sqrt(std::max(0.0, d2 + 1.96 * sd))};
    return r;
}

}  // namespace demscale::stats
