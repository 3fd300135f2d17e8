// The inputs of Yun & Park (2017) Table 1 and the curve settings, read from a TOML file
// (data/table1.toml is the shipped default). Units at this edge: mm, g, degrees, as in the paper;
// everything is converted to SI on reading.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bridge/mikami.hpp"
#include "similarity/particle_replacement.hpp"

namespace demscale::io {

// Which mass feeds Eq. 5: a solid density (so m̄ = m·S_f³ exactly, the replacement concept),
// or the table's rounded masses (V̂ then varies with R, docs/model.md §1).
enum class MassSource { density, table };

struct TableConfig {
    std::string source;                         // file it came from
    double physical_radius_m = 1e-3;            // R of the real particle (S_f = 1)
    std::vector<double> radii_m;                // Table 1 radii
    std::vector<double> tabulated_masses_kg;    // Table 1 masses (may be empty)
    double mass_resolution_kg = 1e-5;           // rounding step of the tabulated masses (0.01 g)
    std::optional<double> solid_density_kg_per_m3;  // absent: implied by the tabulated masses
    MassSource mass_source = MassSource::density;
    similarity::Liquid liquid;
    bridge::MikamiOptions bridge;
    std::vector<double> exponents{1.0, 3.0};    // candidate k in γ̄ = γ·S_f^k
    double curve_hhat_max = 0.5;
    int curve_points = 101;
    std::string sizes_note;                     // a scene's size distribution, for the table's notes (empty: one radius)
};

// Throws InputError "FILE:LINE: key = value: accepted …" for a missing file, malformed TOML,
// an unknown key (with the nearest valid one), a wrong type or an out-of-range value.
TableConfig load_table_config(const std::string& path);

}  // namespace demscale::io
