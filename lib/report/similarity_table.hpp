// The derived similarity table of Yun & Park (2017) Table 1: for each radius S_f, R, m, V, V̂,
// A, B, C, F̂(0), F_C(0), ĥ_rupture, and for each exponent k: γ̄, F̄_C(0), σ̄(0) and their ratios to
// the physical particle. Plus the similarity groups each k keeps or breaks (from the algebra).
#pragma once

#include <string>
#include <vector>

#include "io/table_config.hpp"
#include "io/table_format.hpp"
#include "report/table1_particles.hpp"

namespace demscale::report {

// Column-name tag of an exponent: 1 → "1", 1.5 → "1p5", −1 → "m1".
std::string exponent_tag(double k);

// Metadata every table and curve file carries: version, variant, normalisation, inputs.
std::vector<std::pair<std::string, std::string>> study_metadata(const io::TableConfig& c, const Table1Particles& p);

io::Table similarity_table(const io::TableConfig& c, const std::vector<double>& exponents);

// One row per similarity group: its name, the k that keeps it invariant, and S_f's exponent in the
// ratio for each requested k (0 = kept).
io::Table similarity_groups_table(const std::vector<double>& exponents);

}  // namespace demscale::report
