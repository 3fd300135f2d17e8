#include "io/particle_state.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "core/input_error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_reader.hpp"
#include "io/table_format.hpp"

namespace demscale::io {

void write_particle_state(const std::filesystem::path& file, const dem::Particles& p) {
    Table t;
    t.title = "demscale particle state (SI)";
    t.columns = {"x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "radius", "density"};
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double rho = p.mass[i] / (4.0 / 3.0 * std::numbers::pi * std::pow(p.radius[i], 3));
        const auto& x = p.position[i];
        const auto& v = p.velocity[i];
        const auto& w = p.angular_velocity[i];
        t.rows.push_back({x.x(), x.y(), x.z(), v.x(), v.y(), v.z(), w.x(), w.y(), w.z(), p.radius[i], rho});
    }
    write_file_atomically(file, render(t, Format::csv));
}

dem::Particles read_particle_state(const std::string& path) {
    const CsvData d = read_csv_file(path);
    if (d.header != std::vector<std::string>{"x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "radius", "density"})
        throw InputError(path, "(header)", "x,y,z,vx,vy,vz,wx,wy,wz,radius,density as written by demscale");
    dem::Particles p;
    for (std::size_t k = 0; k < d.rows.size(); ++k) {
        double v[11];
        for (int c = 0; c < 11; ++c) {
            char* end = nullptr;
            v[c] = std::strtod(d.rows[k][c].c_str(), &end);
            if (end == d.rows[k][c].c_str())
                throw InputError(path + ":" + std::to_string(d.row_lines[k]), d.rows[k][c], "a number in column " + d.header[c]);
        }
        const std::size_t i = p.add({v[0], v[1], v[2]}, v[9], v[10], {v[3], v[4], v[5]});
        p.angular_velocity[i] = {v[6], v[7], v[8]};
    }
    return p;
}

}  // namespace demscale::io
