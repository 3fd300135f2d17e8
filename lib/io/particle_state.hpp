// A particle state as CSV (SI units: x,y,z,vx,vy,vz,wx,wy,wz,radius,density), to hand a settled
// fill from one run to another (piles from other engines: io/pile_file.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "dem/particles.hpp"

namespace demscale::io {

void write_particle_state(const std::filesystem::path& file, const dem::Particles& p);
// Throws InputError naming file and line for a missing or ill-formed file.
dem::Particles read_particle_state(const std::string& path);

}  // namespace demscale::io
