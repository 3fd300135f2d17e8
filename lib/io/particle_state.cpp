#include "io/particle_state.hpp"

#include "io/input_file.hpp"

#include <fstream>
#include <numbers>
#include <sstream>
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

dem::Particles read_liggghts_dump(const std::string& path, double density) {
    std::istringstream in(read_input_file("--dump", path, "a readable LIGGGHTS dump file"));
    std::string line;
    std::vector<std::string> columns;
    dem::Particles p;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        if (line.rfind("ITEM: TIMESTEP", 0) == 0) p = dem::Particles{};  // keep the last snapshot
        if (line.rfind("ITEM: ATOMS", 0) == 0) {
            columns.clear();
            std::istringstream h(line.substr(11));
            for (std::string c; h >> c;) columns.push_back(c);
            continue;
        }
        if (columns.empty() || line.rfind("ITEM:", 0) == 0) continue;
        std::istringstream row(line);
        double x = 0, y = 0, z = 0, r = 0;
        std::string value;
        for (const auto& c : columns) {
            row >> value;
            const double v = std::strtod(value.c_str(), nullptr);
            if (c == "x") x = v;
            else if (c == "y") y = v;
            else if (c == "z") z = v;
            else if (c == "radius") r = v;
        }
        if (!row || !(r > 0)) throw InputError(path + ":" + std::to_string(n), line, "a row with x y z radius");
        p.add({x, y, z}, r, density);
    }
    if (p.size() == 0) throw InputError(path, "(no atoms)", "an 'ITEM: ATOMS ... x y z radius' section");
    return p;
}

}  // namespace demscale::io
