// Stress-based similarity (Yun & Park 2017 Eqs. 11–12) for any surface-tension exponent k:
// γ̄ = γ·S_f^k, F̄ = force_scale·R̄·γ̄·F̂ (Eq. 1), σ̄ = F̄ / (πR̄²) (Eq. 11's definition).
// With the printed 2πRγ this is σ̄ = 2F̂γS_f^(k−1)/R; with Mikami's πRγ it is half of that.
#pragma once

#include <string>
#include <vector>

#include "bridge/mikami.hpp"
#include "similarity/dimension.hpp"

namespace demscale::similarity {

struct StressSimilarity {
    double exponent = 0;        // k
    double gamma_n_per_m = 0;   // γ̄ = γ·S_f^k
    double force_n = 0;         // F̄ at the given F̂
    double sigma_pa = 0;        // σ̄ = F̄/(πR̄²), Eq. 11
};

// R̄ in m, physical γ in N/m; fhat is the regression value F̂ for this pair.
StressSimilarity stress_similarity(const bridge::MikamiCoefficients& k, double fhat, double radius_m,
                                   double physical_gamma_n_per_m, double sf, double exponent);

// --- Exponents from the similarity algebra ---------------------------------------------------
// Particle replacement uses the basis S_L = S_f, S_ρ = 1, S_T = S_f^time_exponent, and applies
// γ̄ = γ·S_f^k regardless of what that basis demands of surface tension.

// S_f exponent of a quantity of dimension d under that basis.
double replacement_exponent(Dimension d, double time_exponent);

// S_f exponent of the bridge force when γ̄ = γ·S_f^k. From F = γ·R·f(V̂, ĥ, θ): k + exponent(length).
double bridge_force_exponent(double k);

// The k that keeps the ratio (bridge force) / X invariant under replacement, X of dimension d:
// k + exponent(length) = exponent(X). E.g. X = area → stress (k = 1); X = mass → force per mass (k = 2).
double exponent_keeping_ratio(Dimension d, double time_exponent);

// A similarity group of the bridge force, named and derived, for tables and reports.
struct SimilarityGroup {
    std::string name;          // what it compares
    Dimension reference;       // X in F/X
    double time_exponent;      // S_T = S_f^t assumed (matters only if X has a time dimension)
    double keeping_exponent;   // the k that keeps it invariant
};
std::vector<SimilarityGroup> bridge_similarity_groups();

// S_f exponent of F/X for a given k: bridge_force_exponent(k) − exponent(X).
double group_ratio_exponent(const SimilarityGroup& g, double k);

}  // namespace demscale::similarity
