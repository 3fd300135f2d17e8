// A pile written by any engine, read so that demscale measures it with its own code (SI inside;
// docs/file-formats.md, "Pile files"). Three kinds, told apart by their first lines:
//  - a LIGGGHTS or LAMMPS text dump ("ITEM: ATOMS" then columns named in any order: x y z (or
//    xu yu zu) and radius (or diameter), optionally density); the last snapshot is the pile;
//  - a CSV with columns x, y, z and radius (or r) in metres, or x_mm, y_mm, z_mm and radius_mm (or
//    r_mm) as `demscale slump` writes them, optionally density (kg/m³);
//  - demscale's particle state (settled.csv of `export liggghts`), a CSV of the first kind.
// Spheres without a density column get `density`; velocities (vx vy vz, m/s) are read where all
// three columns are there, else zero.
#pragma once

#include <string>

#include "dem/particles.hpp"

namespace demscale::io {

struct PileFile {
    dem::Particles particles;
    std::string kind;  // "dump" or "csv"
    int snapshots = 1;  // a dump's snapshots (the last one is read)
    bool velocities = false;  // the file gave them (vx vy vz)
};

// Throws InputError naming the file, line and column of the first bad field (a value that is not a
// finite number, a radius ≤ 0, a missing column, a dump whose last snapshot holds fewer atoms than
// its NUMBER OF ATOMS line, or no sphere at all). option: the command-line option that named it.
PileFile read_pile_file(const std::string& option, const std::string& path, double density);
PileFile parse_pile(const std::string& text, const std::string& source, double density);

}  // namespace demscale::io
