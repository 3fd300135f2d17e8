// ParaView output: particles as VTK XML PolyData (.vtp, ASCII) with radius, velocity, angular
// velocity, species and contact count, and a .pvd collection that orders snapshots in time.
// Every file is written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dem/particles.hpp"

namespace demscale::io {

// Number of touching neighbours of each particle (surfaces overlapping).
std::vector<int> contact_counts(const dem::Particles& p);

void write_vtp(const std::filesystem::path& file, const dem::Particles& p);

// A time series of .vtp files described by one .pvd file, rewritten after every added frame.
class VtkSeries {
public:
    explicit VtkSeries(std::filesystem::path pvd_file) : pvd_(std::move(pvd_file)) {}
    void add(double time, const dem::Particles& p);  // writes <stem>_<n>.vtp beside the .pvd

private:
    std::filesystem::path pvd_;
    std::vector<std::pair<double, std::string>> frames_;
};

}  // namespace demscale::io
