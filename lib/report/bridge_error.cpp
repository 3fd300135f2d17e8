#include "report/bridge_error.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "bridge/bridge_cost.hpp"
#include "bridge/bridge_model.hpp"
#include "bridge/bridge_table.hpp"
#include "bridge/mikami.hpp"
#include "bridge/young_laplace.hpp"
#include "core/input_error.hpp"
#include "core/version.hpp"
#include "io/bridge_table_file.hpp"
#include "stats/summary.hpp"

namespace demscale::report {

namespace {

const std::vector<std::string> compared = {"mikami1998", "yun-park-2017", "willett", "willett-simple", "toroidal", "table"};

std::string column_of(const std::string& model) {
    std::string c = "fhat_" + model;
    std::replace(c.begin(), c.end(), '-', '_');
    return c == "fhat_mikami1998" ? "fhat_mikami" : c;
}

// Relative error with the conventions the summary states: both zero → 0; exact zero → skipped.
std::optional<double> relative_error(double model, double exact) {
    if (exact == 0.0) return model == 0.0 ? std::optional(0.0) : std::nullopt;
    return (model - exact) / exact;
}

std::vector<double> log_space(double lo, double hi, int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * i / std::max(n - 1, 1)));
    return v;
}

}  // namespace

BridgeErrorGrid default_bridge_error_grid(bool quick) {
    if (quick) return {log_space(1e-5, 0.3, 3), {0, 40}, {0, 0.5, 0.9}, log_space(1e-5, 0.1, 3), {0, 40}};
    return {log_space(1e-5, 0.3, 8), {0, 20, 40, 60}, {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.99},
            log_space(1e-5, 0.1, 9), {0, 10, 20, 30, 40}};
}

namespace {

using Models = std::map<std::string, std::unique_ptr<bridge::BridgeModel>>;
using Errors = std::map<std::string, std::vector<double>>;  // per model, relative errors

const std::vector<double>& of(const Errors& e, const std::string& model) {
    static const std::vector<double> none;
    const auto it = e.find(model);
    return it == e.end() ? none : it->second;
}

// Every model against the exact sphere-sphere bridge on the grid: study.points and outside_scope;
// the force and rupture-distance errors per model.
void compare_sphere_sphere(const BridgeErrorGrid& grid, const std::string& table_path, const bridge::BridgeTable& table,
                           Models& models, BridgeErrorStudy& study, Errors& errors, Errors& rupture_errors,
                           const std::function<void(int, int)>& progress) {
    auto& pts = study.points;
    pts.title = "Bridge models against the exact Young-Laplace solution (equal spheres)";
    pts.metadata = {{"demscale", version},
                    {"fhat", "F/(2 pi R gamma); hhat = full gap / R; x = hhat / hhat_rupture of the exact solution"},
                    {"table", table_path}};
    pts.columns = {"vhat", "theta_deg", "x", "hhat", "fhat_exact"};
    for (const auto& m : compared) pts.columns.push_back(column_of(m));

    const int total = static_cast<int>(grid.vhat.size() * grid.theta_deg.size());
    int done = 0;
    for (double vhat : grid.vhat) {
        for (double deg : grid.theta_deg) {
            const ContactAngle theta{Degrees{deg}};
            const bridge::YoungLaplaceBridge exact(vhat, theta);
            if (progress) progress(++done, total);
            if (!exact.family_ok()) {
                study.outside_scope += grid.gap_fraction.size();
                continue;
            }
            const bool table_covers = table.covers(vhat, theta);
            for (const auto& m : compared) {
                if (m == "table" && !table_covers) continue;
                rupture_errors[m].push_back(models[m]->hhat_rupture(vhat, theta) / exact.hhat_rupture() - 1.0);
            }
            for (double x : grid.gap_fraction) {
                const double hhat = x * exact.hhat_rupture();
                const auto e = exact.solve(hhat);
                if (!e.ok()) {
                    ++study.outside_scope;
                    continue;
                }
                std::vector<io::Cell> row = {vhat, deg, x, hhat, e.shape.fhat_neck};
                for (const auto& m : compared) {
                    if (m == "table" && !table_covers) {
                        row.push_back(std::string(""));  // the table does not reach this θ
                        continue;
                    }
                    const double f = models[m]->fhat(vhat, theta, hhat);
                    row.push_back(f);
                    if (auto r = relative_error(f, e.shape.fhat_neck)) errors[m].push_back(*r);
                }
                pts.rows.push_back(std::move(row));
            }
        }
    }

}

// The summary's rows of the compared models: error statistics and the cost of one evaluation.
void summarize_models(const BridgeErrorGrid& grid, Models& models, const Errors& errors, const Errors& rupture_errors,
                      double cost_seconds_per_run, BridgeErrorStudy& study) {
    auto& sum = study.summary;
    sum.title = "Bridge model accuracy and cost (errors relative to the exact solution)";
    sum.metadata = {{"grid", std::to_string(grid.vhat.size()) + " V^ x " + std::to_string(grid.theta_deg.size()) +
                                 " theta x " + std::to_string(grid.gap_fraction.size()) + " h^/h^_c"},
                    {"outside_solver_scope", std::to_string(study.outside_scope) + " grid points (bulging bridges)"},
                    {"sphere-wall row", "Mikami's wall fit against the exact sphere-plane bridge: " + std::to_string(grid.wall_vhat.size()) +
                                            " V^ x " + std::to_string(grid.wall_theta_deg.size()) + " theta x " +
                                            std::to_string(grid.gap_fraction.size()) + " h^/h^_c (bridge_wall_error.csv)"},
                    {"cost", "ns per force evaluation at V^ = 0.05544, theta = 0 (per-pair setup cached)"}};
    sum.columns = {"model", "points", "max_abs_rel_error", "median_abs_rel_error", "fraction_over_5pct",
                   "fraction_over_20pct", "max_abs_rupture_error", "ns_per_evaluation"};
    const ContactAngle zero{Degrees{0}};
    for (const auto& m : compared) {
        std::vector<double> a;
        for (double e : of(errors, m)) a.push_back(std::abs(e));
        std::vector<double> ra;
        for (double e : of(rupture_errors, m)) ra.push_back(std::abs(e));
        const double n = std::max<double>(static_cast<double>(a.size()), 1.0);
        const auto over = [&](double t) { return static_cast<double>(std::count_if(a.begin(), a.end(), [t](double x) { return x > t; })) / n; };
        const auto cost = bridge::measure_evaluation_cost(*models[m], 0.05544, zero, cost_seconds_per_run);
        sum.rows.push_back({m, static_cast<double>(a.size()), a.empty() ? 0.0 : *std::max_element(a.begin(), a.end()),
                            stats::median(a), over(0.05), over(0.20), ra.empty() ? 0.0 : *std::max_element(ra.begin(), ra.end()),
                            cost.ns_per_evaluation});
    }
}

// Mikami's sphere–wall fit, the law of the scenes' wet walls, against the exact sphere–plane
// bridge with both surfaces at θ (docs/bridge-models.md): study.wall and its summary row.
void compare_sphere_wall(const BridgeErrorGrid& grid, BridgeErrorStudy& study) {
    auto& sum = study.summary;
    auto& wall = study.wall;
    wall.title = "Mikami's sphere-wall fit against the exact sphere-plane bridge (sphere and wall at theta)";
    wall.metadata = {{"fhat", "F/(2 pi R gamma); hhat = gap to the wall / R; x = hhat / hhat_rupture of the exact solution"}};
    wall.columns = {"vhat", "theta_deg", "x", "hhat", "fhat_exact", "fhat_mikami_wall", "rel_error", "rupture_ratio"};
    std::vector<double> wall_errors, wall_rupture_errors;
    std::size_t wall_outside = 0;
    for (double vhat : grid.wall_vhat)
        for (double deg : grid.wall_theta_deg) {
            const ContactAngle theta{Degrees{deg}};
            const auto exact = bridge::YoungLaplaceBridge::sphere_plane(vhat, theta, theta);
            if (!exact.family_ok()) {
                wall_outside += grid.gap_fraction.size();
                continue;
            }
            const auto k = bridge::mikami_coefficients(vhat, theta, {}, bridge::BridgeGeometry::sphere_wall);
            const double rupture_ratio = k.hhat_rupture / exact.hhat_rupture();
            wall_rupture_errors.push_back(rupture_ratio - 1);
            for (double x : grid.gap_fraction) {
                const double hhat = x * exact.hhat_rupture();
                const auto e = exact.solve(hhat);
                if (!e.ok()) {
                    ++wall_outside;
                    continue;
                }
                const double f = bridge::f_over_2pi_r_gamma(k, bridge::mikami_fhat(k, hhat));
                const auto r = relative_error(f, e.shape.fhat_neck);
                if (r) wall_errors.push_back(std::abs(*r));
                wall.rows.push_back({vhat, deg, x, hhat, e.shape.fhat_neck, f, r ? io::Cell(*r) : io::Cell(io::not_available), rupture_ratio});
            }
        }
    if (wall_outside > 0) wall.notes.push_back(std::to_string(wall_outside) + " grid points without a concave exact bridge left out");
    {
        const auto over = [&](double t) {
            return static_cast<double>(std::count_if(wall_errors.begin(), wall_errors.end(), [t](double x) { return x > t; })) /
                   std::max<double>(static_cast<double>(wall_errors.size()), 1.0);
        };
        double rupture = 0;
        for (double e : wall_rupture_errors) rupture = std::max(rupture, std::abs(e));
        sum.rows.push_back({std::string("mikami1998 sphere-wall"), static_cast<double>(wall_errors.size()),
                            wall_errors.empty() ? 0.0 : *std::max_element(wall_errors.begin(), wall_errors.end()), stats::median(wall_errors),
                            over(0.05), over(0.20), rupture, io::not_available});
    }
}

// Mikami's relative error over V^ and the gap at θ = 0, for the error map figure.
io::Table mikami_error_map(int map_vhat_points, int map_gap_points) {
    const ContactAngle zero{Degrees{0}};
    io::Table map;
    map.title = "Relative error of mikami1998 against the exact bridge, theta = 0";
    map.columns = {"vhat", "x", "rel_error"};
    const auto mikami = bridge::make_bridge_model("mikami1998");
    for (double vhat : log_space(1e-5, 0.3, map_vhat_points)) {
        const bridge::YoungLaplaceBridge exact(vhat, zero);
        if (!exact.family_ok()) continue;
        for (int i = 0; i < map_gap_points; ++i) {
            const double x = 0.99 * i / std::max(map_gap_points - 1, 1);
            const auto e = exact.solve(x * exact.hhat_rupture());
            if (!e.ok()) continue;
            const auto r = relative_error(mikami->fhat(vhat, zero, x * exact.hhat_rupture()), e.shape.fhat_neck);
            map.rows.push_back({vhat, x, r ? *r : 0.0});
        }
    }
    return map;
}

}  // namespace

BridgeErrorStudy bridge_error_study(const BridgeErrorGrid& grid, const std::string& table_path, int map_vhat_points,
                                    int map_gap_points, double cost_seconds_per_run, const std::function<void(int, int)>& progress) {
    const auto table = io::read_bridge_table(table_path);
    Models models;
    for (const auto& name : compared) models[name] = bridge::make_bridge_model(name, &table);
    BridgeErrorStudy study;
    Errors errors, rupture_errors;
    compare_sphere_sphere(grid, table_path, table, models, study, errors, rupture_errors, progress);
    summarize_models(grid, models, errors, rupture_errors, cost_seconds_per_run, study);
    compare_sphere_wall(grid, study);
    {
        const ContactAngle zero{Degrees{0}};
        const auto exact_model = bridge::make_bridge_model("exact");
        const auto cost = bridge::measure_evaluation_cost(*exact_model, 0.05544, zero, cost_seconds_per_run, 3);
        study.summary.rows.push_back({std::string("exact"), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, cost.ns_per_evaluation});
    }
    study.mikami_map = mikami_error_map(map_vhat_points, map_gap_points);
    return study;
}

}  // namespace demscale::report
