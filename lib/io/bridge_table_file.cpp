#include "io/bridge_table_file.hpp"

#include <cmath>
#include <sstream>

#include "core/input_error.hpp"
#include "io/csv_reader.hpp"

namespace demscale::io {

std::string bridge_table_csv(const bridge::BridgeTable& table) {
    const auto& g = table.grid();
    std::ostringstream out;
    out << "# demscale tabulated Young-Laplace bridge between equal spheres (generate: demscale bridge-table)\n"
        << "# fhat = F/(2 pi R gamma); hhat = full gap / R; x = hhat/hhat_rupture = (1 - cos(pi t))/2, t uniform\n"
        << "# grid: vhat_min=" << format_number(g.vhat_min) << " vhat_max=" << format_number(g.vhat_max)
        << " vhat_points=" << g.vhat_points << " theta_max_deg=" << format_number(g.theta_max_deg)
        << " theta_points=" << g.theta_points << " gap_points=" << g.gap_points << "\n"
        << "vhat,theta_deg,x,hhat_rupture,fhat\n";
    for (int iv = 0; iv < g.vhat_points; ++iv)
        for (int it = 0; it < g.theta_points; ++it)
            for (int ix = 0; ix < g.gap_points; ++ix)
                out << format_number(table.node_vhat(iv)) << "," << format_number(table.node_theta_deg(it)) << ","
                    << format_number(table.node_gap_fraction(ix)) << "," << format_number(table.node_hhat_rupture(iv, it)) << ","
                    << format_number(table.node_fhat(iv, it, ix)) << "\n";
    return out.str();
}

bridge::BridgeTable read_bridge_table(const std::string& path) {
    const CsvData csv = read_csv_file(path);
    bridge::BridgeTableGrid g;
    bool have_grid = false;
    for (const auto& line : csv.comments) {
        if (line.rfind("grid:", 0) != 0) continue;
        std::istringstream in(line.substr(5));
        std::string item;
        while (in >> item) {
            const auto eq = item.find('=');
            const std::string key = item.substr(0, eq);
            const double value = std::strtod(item.substr(eq + 1).c_str(), nullptr);
            if (key == "vhat_min") g.vhat_min = value;
            else if (key == "vhat_max") g.vhat_max = value;
            else if (key == "vhat_points") g.vhat_points = static_cast<int>(value);
            else if (key == "theta_max_deg") g.theta_max_deg = value;
            else if (key == "theta_points") g.theta_points = static_cast<int>(value);
            else if (key == "gap_points") g.gap_points = static_cast<int>(value);
        }
        have_grid = true;
    }
    const std::size_t expected = static_cast<std::size_t>(g.vhat_points) * g.theta_points * g.gap_points;
    if (!have_grid || g.vhat_points < 2 || g.theta_points < 2 || g.gap_points < 2 || !(g.vhat_min > 0) ||
        !(g.vhat_max > g.vhat_min))
        throw InputError(path, "(grid line)", "a '# grid: ...' line as written by demscale bridge-table");
    if (csv.header != std::vector<std::string>{"vhat", "theta_deg", "x", "hhat_rupture", "fhat"} || csv.rows.size() != expected)
        throw InputError(path, std::to_string(csv.rows.size()) + " rows",
                         std::to_string(expected) + " rows of vhat,theta_deg,x,hhat_rupture,fhat");
    std::vector<double> fhat(expected), hc(static_cast<std::size_t>(g.vhat_points) * g.theta_points);
    for (std::size_t i = 0; i < expected; ++i) {
        const double h = std::strtod(csv.rows[i][3].c_str(), nullptr), f = std::strtod(csv.rows[i][4].c_str(), nullptr);
        if (!(std::isfinite(f) && f >= 0 && std::isfinite(h) && h > 0))
            throw InputError(path + ":" + std::to_string(csv.row_lines[i]), csv.rows[i][4], "finite fhat >= 0 and hhat_rupture > 0");
        if (!(f > 0)) throw InputError(path + ":" + std::to_string(csv.row_lines[i]), csv.rows[i][4], "fhat > 0 (stable bridges only)");
        fhat[i] = f;
        hc[i / g.gap_points] = h;
    }
    return bridge::BridgeTable::from_nodes(g, fhat, hc);
}

}  // namespace demscale::io
