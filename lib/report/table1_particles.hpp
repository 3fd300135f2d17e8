// The particles of a Table 1 style study: the physical particle and one per tabulated radius,
// with masses from a solid density (replacement, Eqs. 9–10) or from the table as printed.
// Also the density Table 1's masses imply, since the paper does not print one.
#pragma once

#include <optional>
#include <vector>

#include "io/table_config.hpp"
#include "similarity/particle_replacement.hpp"

namespace demscale::report {

struct DensityFit {
    double least_squares_kg_per_m3 = 0;  // argmin Σ (m_i − ρ·V_i)²  =  Σ m_i V_i / Σ V_i²
    // Densities for which every tabulated mass rounds to its printed value (± resolution/2); empty if none.
    std::optional<double> consistent_min_kg_per_m3, consistent_max_kg_per_m3;
};

// Radii in m, masses in kg, resolution = rounding step of the masses in kg.
DensityFit fit_density(const std::vector<double>& radii_m, const std::vector<double>& masses_kg,
                       double mass_resolution_kg);

struct Table1Particles {
    double solid_density_kg_per_m3 = 0;  // used for masses (given, or the least-squares fit)
    std::optional<DensityFit> fit;       // when masses are tabulated
    similarity::ParticleDescription physical;
    std::vector<similarity::ParticleDescription> rows;          // one per radius, config order
    std::vector<std::optional<double>> tabulated_mass_kg;        // per row, if given
};

Table1Particles table1_particles(const io::TableConfig& config);

}  // namespace demscale::report
