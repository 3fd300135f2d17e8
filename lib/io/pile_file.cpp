#include "io/pile_file.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/input_error.hpp"
#include "io/csv_reader.hpp"
#include "io/input_file.hpp"

namespace demscale::io {

namespace {

// Where the position, radius and density of a sphere sit in a row; -1: absent.
struct Columns {
    int x = -1, y = -1, z = -1, radius = -1, density = -1;
    int vx = -1, vy = -1, vz = -1;  // velocity, m/s (all three or none)
    double length_unit = 1;    // m per unit of the file's lengths
    bool diameter = false;     // the size column is a diameter
};

int index_of(const std::vector<std::string>& names, std::initializer_list<const char*> any) {
    for (const char* a : any) {
        const auto it = std::find(names.begin(), names.end(), a);
        if (it != names.end()) return static_cast<int>(it - names.begin());
    }
    return -1;
}

// One sphere from a row's fields; where(column) names the field in a message.
template <class Where>
void add_sphere(dem::Particles& p, const std::vector<std::string>& fields, const std::vector<std::string>& names, const Columns& c,
                double density, Where where) {
    auto at = [&](int col) { return where(col) + " (" + names[static_cast<std::size_t>(col)] + ")"; };
    auto number = [&](int col, const std::string& accepted) {
        const std::string& f = fields[static_cast<std::size_t>(col)];
        const auto x = finite_number(f);
        if (!x) throw InputError(at(col), f.empty() ? "(empty)" : f, accepted);
        return *x;
    };
    const double x = number(c.x, "a finite number") * c.length_unit, y = number(c.y, "a finite number") * c.length_unit,
                 z = number(c.z, "a finite number") * c.length_unit;
    double r = number(c.radius, "a finite number > 0");
    if (!(r > 0)) throw InputError(at(c.radius), fields[static_cast<std::size_t>(c.radius)], "a finite number > 0");
    r *= c.length_unit * (c.diameter ? 0.5 : 1.0);
    double rho = density;
    if (c.density >= 0) {
        rho = number(c.density, "a density > 0 in kg/m^3");
        if (!(rho > 0)) throw InputError(at(c.density), fields[static_cast<std::size_t>(c.density)], "a density > 0 in kg/m^3");
    }
    dem::Vec3 v = dem::Vec3::Zero();
    if (c.vx >= 0) v = {number(c.vx, "a finite velocity"), number(c.vy, "a finite velocity"), number(c.vz, "a finite velocity")};
    p.add({x, y, z}, r, rho, v);
}

// Velocity columns, when all three are there.
void find_velocity(Columns& c, const std::vector<std::string>& names) {
    c.vx = index_of(names, {"vx"}), c.vy = index_of(names, {"vy"}), c.vz = index_of(names, {"vz"});
    if (c.vx < 0 || c.vy < 0 || c.vz < 0) c.vx = c.vy = c.vz = -1;
}

// "ITEM: ATOMS id type x y z radius ...": the columns, checked on the header's line.
Columns dump_columns(const std::vector<std::string>& names, const std::string& where) {
    Columns c;
    c.x = index_of(names, {"x", "xu"}), c.y = index_of(names, {"y", "yu"}), c.z = index_of(names, {"z", "zu"});
    c.radius = index_of(names, {"radius"});
    if (c.radius < 0) c.radius = index_of(names, {"diameter"}), c.diameter = true;
    c.density = index_of(names, {"density"});
    find_velocity(c, names);
    std::string listed;
    for (const auto& n : names) listed += (listed.empty() ? "" : " ") + n;
    if (c.x < 0 || c.y < 0 || c.z < 0)
        throw InputError(where + " (ATOMS columns)", listed.empty() ? "(none)" : listed,
                         index_of(names, {"xs"}) >= 0 ? "unscaled coordinates x y z or xu yu zu (dump custom ... x y z radius), not xs ys zs"
                                                      : "columns x y z (or xu yu zu) and radius (or diameter)");
    if (c.radius < 0) throw InputError(where + " (ATOMS columns)", listed, "a radius (or diameter) column: dump custom ... x y z radius");
    return c;
}

PileFile parse_dump(const std::string& text, const std::string& source, double density) {
    PileFile pile;
    pile.kind = "dump";
    pile.snapshots = 0;
    std::istringstream in(text);
    std::string line, count_line;
    std::vector<std::string> names;
    Columns columns;
    long expected = -1;
    bool atoms = false, read_count = false;
    for (int n = 1; std::getline(in, line); ++n) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string at = source + ":" + std::to_string(n);
        if (line.rfind("ITEM:", 0) == 0) {
            atoms = false;
            if (line.rfind("ITEM: TIMESTEP", 0) == 0) pile.particles = dem::Particles{}, ++pile.snapshots, expected = -1;
            read_count = line.rfind("ITEM: NUMBER OF ATOMS", 0) == 0;
            if (line.rfind("ITEM: ATOMS", 0) == 0) {
                std::istringstream h(line.substr(11));
                names.clear();
                for (std::string c; h >> c;) names.push_back(c);
                columns = dump_columns(names, at);
                pile.velocities = columns.vx >= 0;
                atoms = true;
                count_line = at;
            }
            continue;
        }
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (read_count) {
            const auto v = finite_number(line);
            if (!v || *v < 0 || *v != std::floor(*v)) throw InputError(at + ":1 (NUMBER OF ATOMS)", line, "a whole number >= 0");
            expected = static_cast<long>(*v), read_count = false;
            continue;
        }
        if (!atoms) continue;  // box bounds and the like
        std::istringstream row(line);
        std::vector<std::string> fields;
        for (std::string f; row >> f;) fields.push_back(f);
        if (fields.size() != names.size()) {
            const std::size_t col = std::min(fields.size(), names.size());
            throw InputError(at + ":" + std::to_string(col + 1), fields.size() < names.size() ? "(missing)" : fields[col],
                             std::to_string(names.size()) + " values, one per column of the ATOMS line");
        }
        add_sphere(pile.particles, fields, names, columns, density,
                   [&](int col) { return at + ":" + std::to_string(col + 1); });
    }
    if (pile.snapshots == 0 && !names.empty()) pile.snapshots = 1;  // ATOMS without a TIMESTEP item
    if (names.empty()) throw InputError(source, "(no ITEM: ATOMS line)", "a LIGGGHTS or LAMMPS text dump with an 'ITEM: ATOMS ... x y z radius' section");
    if (expected >= 0 && static_cast<long>(pile.particles.size()) != expected)
        throw InputError(count_line + " (ATOMS)", std::to_string(pile.particles.size()) + " rows",
                         std::to_string(expected) + " rows, as its NUMBER OF ATOMS says (a dump cut short?)");
    return pile;
}

PileFile parse_csv_pile(const std::string& text, const std::string& source, double density) {
    const CsvData d = parse_csv(text, source);
    Columns c;
    c.x = index_of(d.header, {"x"}), c.y = index_of(d.header, {"y"}), c.z = index_of(d.header, {"z"});
    c.radius = index_of(d.header, {"radius", "r"});
    if (c.x < 0 && c.y < 0 && c.z < 0 && c.radius < 0) {
        c.x = index_of(d.header, {"x_mm"}), c.y = index_of(d.header, {"y_mm"}), c.z = index_of(d.header, {"z_mm"});
        c.radius = index_of(d.header, {"radius_mm", "r_mm"});
        c.length_unit = 1e-3;
    }
    c.density = index_of(d.header, {"density"});
    find_velocity(c, d.header);
    if (c.x < 0 || c.y < 0 || c.z < 0 || c.radius < 0) {
        std::string listed;
        for (const auto& n : d.header) listed += (listed.empty() ? "" : ",") + n;
        throw InputError(source + " (header row)", listed,
                         "the columns x, y, z, radius (or r) in m, or x_mm, y_mm, z_mm, radius_mm (or r_mm); density (kg/m^3) optional");
    }
    PileFile pile;
    pile.kind = "csv";
    pile.velocities = c.vx >= 0;
    for (std::size_t k = 0; k < d.rows.size(); ++k)
        add_sphere(pile.particles, d.rows[k], d.header, c, density,
                   [&](int col) { return source + ":" + std::to_string(d.row_lines[k]) + ":" + std::to_string(col + 1); });
    return pile;
}

}  // namespace

PileFile parse_pile(const std::string& text, const std::string& source, double density) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    PileFile pile = first != std::string::npos && text.compare(first, 5, "ITEM:") == 0 ? parse_dump(text, source, density)
                                                                                         : parse_csv_pile(text, source, density);
    if (pile.particles.size() == 0) throw InputError(source, "(no spheres)", "at least one sphere");
    return pile;
}

PileFile read_pile_file(const std::string& option, const std::string& path, double density) {
    return parse_pile(read_input_file(option, path, "a readable pile file (LIGGGHTS/LAMMPS text dump or CSV)"), path, density);
}

}  // namespace demscale::io
