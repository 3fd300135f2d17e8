// How wrong each bridge model is where a user applies it: every model against the exact
// Young–Laplace solution over a (V̂, θ, ĥ/ĥ_rupture) grid, with a summary per model (error
// statistics, rupture error, cost per evaluation) and the data for a Mikami error map; and
// Mikami's sphere–wall fit against the exact sphere–plane bridge.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/table_format.hpp"

namespace demscale::report {

struct BridgeErrorGrid {
    std::vector<double> vhat;         // default: 8 log-spaced in [1e-5, 0.3]
    std::vector<double> theta_deg;    // default: 0, 20, 40, 60
    std::vector<double> gap_fraction; // ĥ/ĥ_rupture(exact); default 0, 0.1, …, 0.9, 0.99
    // Sphere–wall: Mikami's wall fit against the exact sphere–plane bridge (both surfaces at θ).
    std::vector<double> wall_vhat;       // default: 9 log-spaced in [1e-5, 0.1], its fitted range
    std::vector<double> wall_theta_deg;  // default: 0, 10, 20, 30, 40
};
BridgeErrorGrid default_bridge_error_grid(bool quick);

struct BridgeErrorStudy {
    io::Table points;        // one row per grid point where the exact bridge exists
    io::Table summary;       // one row per model
    io::Table mikami_map;    // θ = 0: relative error of mikami1998 over (V̂, ĥ/ĥ_rupture)
    io::Table wall;          // one row per sphere–wall grid point: Mikami's wall fit against the exact bridge
    std::size_t outside_scope = 0;  // grid points where the exact solver has no concave bridge
};

// table_path: the tabulated model's CSV (its column is left empty where the table does not cover θ).
// map_vhat_points × map_gap_points exact solves for the map (θ = 0). progress(done, total) per (V̂, θ).
BridgeErrorStudy bridge_error_study(const BridgeErrorGrid& grid, const std::string& table_path, int map_vhat_points,
                                    int map_gap_points, double cost_seconds_per_run,
                                    const std::function<void(int, int)>& progress = {});

}  // namespace demscale::report
