// The standard error of a size class's share of the mass among n spheres drawn by number, for the
// size tests: with number weights w_j ∝ f_j / x_j³, the share f_c = n_c x_c³ / Σ n_j x_j³,
// linearised (the delta method), has variance Σ_j w_j x_j⁶ (δ_jc − f_c)² / (n μ²), μ = Σ_j w_j x_j³.
// Written out here from the definitions, not from the library's draw.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

inline double class_mass_fraction_error(const std::vector<double>& x, const std::vector<double>& f, std::size_t c, double n) {
    std::vector<double> w;
    double total = 0, mu = 0, var = 0;
    for (std::size_t j = 0; j < x.size(); ++j) w.push_back(f[j] / std::pow(x[j], 3)), total += w.back();
    for (std::size_t j = 0; j < x.size(); ++j) w[j] /= total, mu += w[j] * std::pow(x[j], 3);
    for (std::size_t j = 0; j < x.size(); ++j) var += w[j] * std::pow(x[j], 6) * std::pow((j == c ? 1.0 : 0.0) - f[c], 2);
    return std::sqrt(var / n) / mu;
}
