#include "similarity/stress_similarity.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/input_error.hpp"
#include "similarity/quantity_catalogue.hpp"

namespace demscale::similarity {

StressSimilarity stress_similarity(const bridge::MikamiCoefficients& k, double fhat, double radius_m,
                                   double physical_gamma_n_per_m, double sf, double exponent) {
    require_positive(sf, "sf");
    require_finite(exponent, "exponent");
    require_positive(radius_m, "radius_m");
    require_positive(physical_gamma_n_per_m, "surface_tension_n_per_m");
    StressSimilarity s;
    s.exponent = exponent;
    s.gamma_n_per_m = physical_gamma_n_per_m * std::pow(sf, exponent);            // Eq. 12 with any k
    s.force_n = bridge::bridge_force_newton(k, fhat, radius_m, s.gamma_n_per_m);   // Eq. 1
    s.sigma_pa = s.force_n / (std::numbers::pi * radius_m * radius_m);             // Eq. 11
    if (!std::isfinite(s.gamma_n_per_m) || !std::isfinite(s.sigma_pa))
        throw std::overflow_error("stress similarity overflows at S_f = " + format_number(sf) +
                                  ", k = " + format_number(exponent));
    return s;
}

double replacement_exponent(Dimension d, double time_exponent) {
    return d.length + d.time * time_exponent;  // S_ρ = 1 contributes nothing
}

double bridge_force_exponent(double k) {
    const Dimension length = find_quantity("length", "length").dimension;
    return k + replacement_exponent(length, 0.0);
}

double exponent_keeping_ratio(Dimension d, double time_exponent) {
    // Solve bridge_force_exponent(k) = replacement_exponent(d): linear in k with unit slope.
    return replacement_exponent(d, time_exponent) - bridge_force_exponent(0.0);
}

std::vector<SimilarityGroup> bridge_similarity_groups() {
    auto dim = [](std::string_view key) { return find_quantity(key, "quantity").dimension; };
    const Dimension weight = dim("mass") * dim("gravity");
    std::vector<SimilarityGroup> g = {
        {"bridge stress F/(pi R^2) (Eq. 11)", dim("area"), 0.0, 0},
        {"capillary force / weight (Bond number, g kept: S_T = S_f^1/2)", weight, 0.5, 0},
        {"capillary force / particle mass", dim("mass"), 0.0, 0},
        {"force under exact scaling with g kept (S_T = S_f^1/2)", dim("force"), 0.5, 0},
        {"force under exact scaling with velocity kept (S_T = S_f)", dim("force"), 1.0, 0},
    };
    for (SimilarityGroup& x : g) x.keeping_exponent = exponent_keeping_ratio(x.reference, x.time_exponent);
    return g;
}

double group_ratio_exponent(const SimilarityGroup& g, double k) {
    return bridge_force_exponent(k) - replacement_exponent(g.reference, g.time_exponent);
}

}  // namespace demscale::similarity
