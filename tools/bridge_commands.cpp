// Subcommands of the liquid-bridge study: bridge (one evaluation), bridge-table (generate the
// tabulated exact model), bridge-error (every model against the exact solution).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <memory>

#include "bridge/bridge_model.hpp"
#include "bridge/bridge_table.hpp"
#include "bridge/mikami.hpp"
#include "bridge/validity.hpp"
#include "bridge/young_laplace.hpp"
#include "cli_common.hpp"
#include "core/input_error.hpp"
#include "io/bridge_table_file.hpp"
#include "io/atomic_file.hpp"
#include "report/bridge_error_files.hpp"

namespace demscale::cli {

namespace {

struct Options {
    double vhat = 0.05544, theta_deg = 0, hhat = 0;
    std::string geometry = "sphere-sphere";
    std::optional<double> theta_wall_deg;  // the wall's contact angle (default: --theta)
    std::string model = "exact";
    std::string format = "text";
    std::string table = default_bridge_table;
    std::string out = "bridge_table.csv";
    std::string out_dir = default_plots;
    bool quick = false, no_png = false;
};

// The exact solution's row: force, rupture, whether a bridge exists, and its shape; an
// explicit refusal where the solver has no concave bridge.
void exact_row(const bridge::YoungLaplaceBridge& family, const Options& o, io::Table& t, std::vector<io::Cell>& row, bool wall) {
    const auto r = family.solve(std::max(o.hhat, 0.0));
    if (r.status == bridge::YoungLaplaceStatus::outside_scope)
        throw InputError("--vhat, --theta", format_number(o.vhat) + ", " + format_number(o.theta_deg),
                         "a concave (pendular) bridge, the exact solver's scope (" + r.message + ")");
    if (r.status == bridge::YoungLaplaceStatus::not_converged) throw std::runtime_error("exact bridge: " + r.message);
    t.columns.insert(t.columns.end(), {"neck_radius_over_r", "filling_angle_deg", "curvature_kappa", "volume_check"});
    if (wall) t.columns.push_back("wall_footprint_over_r");
    row.insert(row.end(), {r.ok() ? r.shape.fhat_neck : 0.0, r.hhat_rupture, r.ok() ? 1.0 : 0.0, std::string("ok")});
    if (r.ok()) {
        row.insert(row.end(), {r.shape.neck_radius, r.shape.filling_angle * 180 / M_PI, r.shape.curvature, r.shape.volume});
        if (wall) row.push_back(r.shape.plate_radius);
    } else {
        row.insert(row.end(), wall ? 5 : 4, io::Cell(std::string("-")));  // no bridge: no shape
        t.notes.push_back(r.message + ": no bridge, force 0");
    }
}

int run_bridge(const Options& o) {
    require_positive(o.vhat, "--vhat");
    require_finite(o.hhat, "--hhat");
    const ContactAngle theta{Degrees{o.theta_deg}};
    const auto format = io::parse_format(o.format, "--format");
    const bool wall = o.geometry == "sphere-wall";
    if (!wall && o.geometry != "sphere-sphere") throw InputError("--geometry", o.geometry, "sphere-sphere or sphere-wall");
    if (o.theta_wall_deg && !wall) throw InputError("--theta-wall", format_number(*o.theta_wall_deg), "only with --geometry sphere-wall");
    const ContactAngle theta_wall = o.theta_wall_deg ? ContactAngle{Degrees{*o.theta_wall_deg}} : theta;
    io::Table t;
    t.title = wall ? "Liquid bridge between a sphere and a flat wall" : "Liquid bridge between equal spheres";
    t.metadata = {{"normalisation", wall ? "f_over_2pi_r_gamma = F/(2 pi R gamma); hhat = gap to the wall / R; vhat = V / R^3"
                                         : "f_over_2pi_r_gamma = F/(2 pi R gamma); hhat = full gap / R; vhat = V / R^3"}};
    if (wall) t.metadata.push_back({"wall contact angle", format_number(o.theta_wall_deg.value_or(o.theta_deg)) + " deg"});
    t.columns = {"model", "vhat", "theta_deg", "hhat", "f_over_2pi_r_gamma", "hhat_rupture", "bridge_exists", "validity"};
    // The flags' codes in the row ("ok": none), each flag's sentence as a note.
    auto flag = [&](const std::vector<bridge::ValidityWarning>& flags) {
        std::string codes;
        for (const auto& f : flags) codes += (codes.empty() ? "" : ";") + f.code, t.notes.push_back(f.code + ": " + f.message);
        return codes.empty() ? std::string("ok") : codes;
    };
    std::vector<io::Cell> row = {o.model, o.vhat, o.theta_deg, o.hhat};
    if (o.model == "exact") {
        exact_row(wall ? bridge::YoungLaplaceBridge::sphere_plane(o.vhat, theta, theta_wall) : bridge::YoungLaplaceBridge(o.vhat, theta),
                  o, t, row, wall);
        if (o.hhat < 0) t.notes.push_back("h^ < 0 (overlap) evaluated at contact, h^ = 0");
    } else if (wall) {
        // Mikami's sphere–wall fit: one contact angle for sphere and wall.
        const bool mikami = o.model == "mikami1998" || o.model == "yun-park-2017";
        if (!mikami) throw InputError("--model", o.model, "exact, mikami1998 or yun-park-2017 with --geometry sphere-wall (the models with a sphere-wall form)");
        if (o.theta_wall_deg && *o.theta_wall_deg != o.theta_deg)
            throw InputError("--theta-wall", format_number(*o.theta_wall_deg), "--theta's value for Mikami's wall fit (one contact angle)");
        const auto k = bridge::mikami_coefficients(o.vhat, theta, {bridge::parse_mikami_variant(o.model, "--model")},
                                                   bridge::BridgeGeometry::sphere_wall);
        const auto e = bridge::evaluate_mikami(k, o.hhat);
        auto flags = bridge::check_validity(o.vhat, theta, k);
        if (auto c = bridge::clamped_at(k, o.hhat)) flags.push_back(*c);
        const double f = bridge::f_over_2pi_r_gamma(k, e.fhat);
        row.insert(row.end(), {f, k.hhat_rupture, e.bridge_exists && f > 0 ? 1.0 : 0.0, flag(flags)});
        if (!e.bridge_exists) t.notes.push_back("h^ = " + format_number(o.hhat) + " is beyond rupture (" + format_number(k.hhat_rupture) + "): no bridge, force 0");
        t.notes.push_back("Mikami's sphere-wall fit overestimates the exact force (bridge-error, bridge_wall_error.csv)");
    } else {
        std::optional<bridge::BridgeTable> table;
        if (o.model == "table") table = io::read_bridge_table(o.table);
        const auto m = bridge::make_bridge_model(o.model, table ? &*table : nullptr);
        const auto e = bridge::evaluate(*m, o.vhat, theta, o.hhat);
        row.insert(row.end(), {e.fhat, e.hhat_rupture, e.bridge_exists ? 1.0 : 0.0, flag(e.flags)});
        if (o.hhat > e.hhat_rupture)
            t.notes.push_back("h^ = " + format_number(o.hhat) + " is beyond rupture (" + format_number(e.hhat_rupture) + "): no bridge, force 0");
        if (const auto range = m->fitted_range(); !range.stated) t.notes.push_back("fitted range: " + range.source);
    }
    t.rows.push_back(std::move(row));
    std::cout << io::render(t, format);
    return 0;
}

int run_bridge_table(const Options& o) {
    const auto table = bridge::BridgeTable::generate({}, progress_printer("bridge-table (V^, theta) nodes"));
    io::write_file_atomically(o.out, io::bridge_table_csv(table));
    std::cout << "wrote " << o.out << "\n";
    return 0;
}

int run_bridge_error(const Options& o) {
    const auto format = io::parse_format(o.format, "--format");
    const auto grid = report::default_bridge_error_grid(o.quick);
    const auto study = report::bridge_error_study(grid, o.table, o.quick ? 4 : 16, o.quick ? 5 : 21,
                                                  o.quick ? 0.02 : 0.2, progress_printer("bridge-error (V^, theta)"));
    const auto files = report::write_bridge_error_files(study, o.out_dir, !o.no_png);
    if (format == io::Format::csv) {
        std::cout << io::render(study.points, format);
        return 0;
    }
    std::cout << io::render(study.summary, format);
    for (const auto& f : files) std::cerr << "wrote " << f.string() << "\n";
    return 0;
}

}  // namespace

std::vector<Command> bridge_commands(CLI::App& app) {
    auto o = std::make_shared<Options>();
    std::string names;
    for (auto n : bridge::bridge_model_names()) names += (names.empty() ? "" : "|") + std::string(n);

    auto* one = app.add_subcommand("bridge", "one liquid-bridge force evaluation with any model");
    one->add_option("--vhat", o->vhat, "liquid volume V/R^3")->capture_default_str();
    one->add_option("--theta", o->theta_deg, "contact angle in degrees, [0, 90)")->capture_default_str();
    one->add_option("--hhat", o->hhat, "full surface gap / R")->capture_default_str();
    one->add_option("--model", o->model, names)->capture_default_str();
    one->add_option("--table", o->table, "tabulated model (default: data/bridge_table.csv)");
    one->add_option("--geometry", o->geometry, "sphere-sphere | sphere-wall (a sphere above a flat wall: exact, mikami1998, yun-park-2017)")
        ->capture_default_str();
    one->add_option("--theta-wall", o->theta_wall_deg, "the wall's contact angle in degrees (default: --theta; exact only)");
    one->add_option("--format", o->format, "text | csv | markdown | json")->capture_default_str();

    auto* gen = app.add_subcommand("bridge-table", "tabulate the exact bridge for --model table (about 20 s)");
    gen->add_option("--out", o->out, "output CSV (default: bridge_table.csv here; --table reads data/bridge_table.csv)");

    auto* err = app.add_subcommand("bridge-error", "every bridge model against the exact Young-Laplace solution");
    err->add_flag("--quick", o->quick, "a small grid (seconds)");
    err->add_option("--out", o->out_dir, "folder for CSV and plots (default: plots/)");
    err->add_option("--table", o->table, "tabulated model (default: data/bridge_table.csv)");
    err->add_option("--format", o->format, "text | csv (points) | markdown | json")->capture_default_str();
    err->add_flag("--no-png", o->no_png, "CSV and gnuplot scripts only");

    return {{one, [o] { return run_bridge(*o); }},
            {gen, [o] { return run_bridge_table(*o); }},
            {err, [o] { return run_bridge_error(*o); }}};
}

}  // namespace demscale::cli
