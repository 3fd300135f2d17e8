// Subcommands of the liquid-bridge study: bridge (one evaluation), bridge-table (generate the
// tabulated exact model), bridge-error (every model against the exact solution), bench (costs).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <memory>

#include "bridge/bridge_cost.hpp"
#include "bridge/bridge_model.hpp"
#include "bridge/bridge_table.hpp"
#include "bridge/mikami.hpp"
#include "bridge/validity.hpp"
#include "bridge/young_laplace.hpp"
#include "cli_common.hpp"
#include "core/core_link.hpp"
#include "core/idle_cores.hpp"
#include "core/input_error.hpp"
#include "io/bridge_table_file.hpp"
#include "io/atomic_file.hpp"
#include "report/bridge_error_files.hpp"
#include "slump/size_sweep.hpp"
#include "slump/slump_run.hpp"
#include <omp.h>

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
    bool quick = false, no_png = false, dem = false, core_link = false;
    std::string scene = shipped("scenes/small_wet.toml");
    double seconds = 0.2;
    std::string sizes;     // bench --dem --sizes: the size sweep
    int size_steps = 100;  // the same at every size
    double size_timed = 1e7;  // particle-steps timed at least per size
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

// Cost of each optional contact law: the scene is filled and settled once, then the lift-and-spread
// phase runs from that same settled fill, dry, wet (Mikami's fit, and the exact bridge tabulated)
// and with SJKR adhesion, under each rolling law
// (each its own compiled engine), for the whole spread time (no stop at rest, so every row steps
// equally). EPSD runs also with Ai's rolling dashpot (η_r = 0.3), and with the energy ledger.
int run_dem_bench(const Options& o) {
    auto scene = load_scene(o.scene);
    scene.rest_duration_s = 1e30;
    slump::SlumpPhases settle;
    settle.settle_only = true;
    std::cerr << "settling " << display_path(o.scene) << " once ..." << std::endl;
    const dem::Particles settled = slump::run_slump(scene, {}, false, settle).final_state;

    io::Table t;
    t.title = "DEM lift-and-spread phase from one settled fill, under each combination of optional laws";
    t.metadata = {{"scene", display_path(o.scene)},
                  {"settled as", scene.wet ? "wet (the scene's own laws)" : "dry (the scene's own laws)"},
                  {"threads", std::to_string(omp_get_max_threads())}};
    t.columns = {"laws", "particles", "steps", "wall_s", "particle_steps_per_s", "cost_vs_dry_same_rolling",
                 "cost_vs_dry_free_rolling", "cost_vs_mikami_same_rolling"};
    struct Combination {
        const char* rolling;
        bool ledger;
        double rolling_damping;  // η_r of EPSD's dashpot
    };
    const Combination combinations[] = {{"", false, 0},       {"+epsd", false, 0}, {"+epsd", false, 0.3},
                                        {"+epsd2", false, 0}, {"+cdt", false, 0},  {"+epsd", true, 0}};
    // Cohesion: none, the Mikami bridge, the exact bridge tabulated (bridge_variant = "table"), SJKR
    // adhesion (the scene's k, else 2e4 J/m³).
    enum class Cohesion { dry, mikami, exact, sjkr };
    const double k_sjkr = scene.cohesion_energy_density > 0 ? scene.cohesion_energy_density : 2e4;
    std::vector<double> dry_rate(std::size(combinations)), mikami_rate(std::size(combinations));
    for (const Cohesion cohesion : {Cohesion::dry, Cohesion::mikami, Cohesion::exact, Cohesion::sjkr})
        for (std::size_t n = 0; n < std::size(combinations); ++n) {
            const std::string rolling = combinations[n].rolling;
            const bool wet = cohesion == Cohesion::mikami || cohesion == Cohesion::exact;
            auto s = scene;
            s.wet = wet;
            s.particle_curve = cohesion == Cohesion::exact ? bridge::CurveSource::exact : bridge::CurveSource::fit;
            s.cohesion_energy_density = cohesion == Cohesion::sjkr ? k_sjkr : 0;
            s.rolling_resistance = !rolling.empty();
            s.rolling_model = rolling == "+cdt"     ? slump::RollingModel::constant_torque
                              : rolling == "+epsd2" ? slump::RollingModel::epsd2
                                                    : slump::RollingModel::epsd;
            s.material.rolling_damping = combinations[n].rolling_damping;
            slump::SlumpPhases phases;
            phases.start = &settled;
            phases.energy_ledger = combinations[n].ledger;
            const auto r = slump::run_slump(s, {}, false, phases);
            const double rate = double(r.particles) * double(r.steps) / r.wall_s;
            if (cohesion == Cohesion::dry) dry_rate[n] = rate;
            if (cohesion == Cohesion::mikami) mikami_rate[n] = rate;
            const std::string dashpot = combinations[n].rolling_damping > 0 ? " dashpot eta_r=" + format_number(combinations[n].rolling_damping) : "";
            const char* laws = cohesion == Cohesion::mikami  ? "hertz+mindlin+mikami"
                               : cohesion == Cohesion::exact ? "hertz+mindlin+exact-table"
                               : cohesion == Cohesion::sjkr  ? "hertz+mindlin+sjkr"
                                                             : "hertz+mindlin";
            t.rows.push_back({std::string(laws) + rolling + dashpot + (combinations[n].ledger ? " +energy ledger" : ""),
                              double(r.particles), double(r.steps), r.wall_s, rate, dry_rate[n] / rate, dry_rate[0] / rate,
                              wet ? io::Cell(mikami_rate[n] / rate) : io::Cell(std::string("-"))});
        }
    std::cout << io::render(t, io::parse_format(o.format, "--format"));
    return 0;
}

// The size sweep: for each size, dry and wet (the scene's liquid), particles in the lattice's order
// and shuffled; each rate against the smallest size's of the same laws and order.
int run_size_sweep(const Options& o) {
    const auto scene = load_scene(o.scene);
    const auto sizes = parse_number_list(o.sizes, "--sizes", 99, 2e7);
    if (o.size_steps < 10 || o.size_steps > 100000) throw InputError("--steps", std::to_string(o.size_steps), "10 to 100000");
    io::Table t;
    t.title = "DEM cost as the work grows: the scene's cone scaled to each size, packed to touching, stepped from rest";
    const auto load = load_average();
    t.metadata = {{"scene", display_path(o.scene)},
                  {"threads", std::to_string(omp_get_max_threads())},
                  {"load average before", load ? format_short(*load, 3) : "unknown"},
                  {"timed", "the difference of runs of S and 3 S steps (set-up excluded), S = " + std::to_string(o.size_steps) +
                                " at every size (the same motion), the pair repeated until " + format_number(o.size_timed) + " particle-steps are timed"},
                  {"contacts", "overlapping pairs of the pile's spheres per sphere at the end of the last run (bridges across a gap not counted): "
                               "the work per particle, larger in deeper beds; contact_steps_per_s = particle_steps_per_s x contacts_per_particle"}};
    t.columns = {"laws", "order", "particles", "steps", "wall_s", "particle_steps_per_s", "rate_vs_smallest",
                 "contacts_per_particle", "contact_steps_per_s", "contact_rate_vs_smallest", "peak_bytes_per_particle"};
    for (const bool wet : {false, true})
        for (const bool shuffled : {false, true}) {
            auto s = scene;
            s.wet = wet;
            double smallest = 0, smallest_per_contact = 0;
            for (double n : sizes) {
                std::cerr << "size sweep: " << (wet ? "wet" : "dry") << (shuffled ? ", shuffled" : "") << ", about " << n
                          << " particles ..." << std::endl;
                const auto point = slump::time_size(s, n, o.size_steps, shuffled, o.size_timed);
                if (smallest == 0) smallest = point.particle_steps_per_s, smallest_per_contact = point.contact_steps_per_s;
                const bool timed = point.particle_steps_per_s > 0 && smallest > 0;  // else the set-up's noise exceeded the steps
                const bool per_contact = timed && point.contact_steps_per_s > 0 && smallest_per_contact > 0;  // 0: no contacts
                const io::Cell untimed(std::string("- (more --steps)")), none(std::string("-"));
                t.rows.push_back({wet ? "hertz+mindlin+mikami" : "hertz+mindlin", shuffled ? "shuffled" : "lattice", double(point.particles),
                                  double(point.steps), point.wall_s, timed ? io::Cell(point.particle_steps_per_s) : untimed,
                                  timed ? io::Cell(point.particle_steps_per_s / smallest) : untimed, point.contacts_per_particle,
                                  per_contact ? io::Cell(point.contact_steps_per_s) : none,
                                  per_contact ? io::Cell(point.contact_steps_per_s / smallest_per_contact) : none,
                                  point.peak_bytes_per_particle > 0 ? io::Cell(point.peak_bytes_per_particle) : io::Cell(std::string("-"))});
            }
        }
    std::cout << io::render(t, io::parse_format(o.format, "--format"));
    return 0;
}

// How dear sharing data between two threads is now (core/core_link.hpp), for the scripts' logs.
int run_core_link(const Options& o) {
    if (o.dem) throw InputError("--core-link", "given with --dem", "on its own (it times two threads, not the engine)");
    const auto link = measure_core_link();
    if (!link) throw InputError("--core-link", "one thread", "a machine where OpenMP runs two threads (OMP_NUM_THREADS >= 2)");
    io::Table t;
    t.title = "Cache lines between two cores: each of two threads updates 4 000 lines, shuffled, 1 500 rounds";
    const auto load = load_average();
    t.metadata = {{"kept", "each thread its own lines"},
                  {"crossing", "each thread the lines the other wrote the round before"},
                  {"load average before", load ? format_short(*load, 3) : "unknown"}};
    t.columns = {"kept_ns_per_line", "crossing_ns_per_line", "crossing_over_kept", "empty_region_us"};
    t.rows.push_back({link->kept_ns, link->crossing_ns, link->crossing_ns / link->kept_ns, link->region_us});
    std::cout << io::render(t, io::parse_format(o.format, "--format"));
    return 0;
}

int run_bench(const Options& o) {
    if (o.core_link) return run_core_link(o);
    if (o.dem && !o.sizes.empty()) return run_size_sweep(o);
    if (!o.sizes.empty()) throw InputError("--sizes", o.sizes, "with --dem (the size sweep benchmarks the DEM engine)");
    if (o.dem) return run_dem_bench(o);
    io::Table t;
    t.title = "Cost of one bridge force evaluation (median of 5 runs, one pair type: per-pair setup cached)";
    t.metadata = {{"pair", "V^ = 0.05544 (Table 1), theta = 0, gaps spread over [0, h^_rupture]"},
                  {"timing", "each run sized to about " + format_number(o.seconds) + " s; ratios taken within this one run"}};
    t.columns = {"model", "ns_per_evaluation", "relative_to_mikami1998", "evaluations_per_run"};
    const ContactAngle zero{Degrees{0}};
    double mikami_ns = 0;
    const auto table = io::read_bridge_table(o.table);
    for (auto name : bridge::bridge_model_names()) {
        const auto m = bridge::make_bridge_model(name, &table);
        const auto c = bridge::measure_evaluation_cost(*m, 0.05544, zero, o.seconds);
        if (name == "mikami1998") mikami_ns = c.ns_per_evaluation;
        t.rows.push_back({std::string(name), c.ns_per_evaluation, 0.0, static_cast<double>(c.evaluations_per_run)});
    }
    for (auto& r : t.rows) r[2] = std::get<double>(r[1]) / mikami_ns;
    std::cout << io::render(t, io::parse_format(o.format, "--format"));
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

    auto* bench = app.add_subcommand("bench", "benchmarks: cost per bridge force evaluation of every model (--dem: DEM engine)");
    bench->add_option("--seconds", o->seconds, "length of each timing run")->capture_default_str()->check(finite_positive);
    bench->add_flag("--core-link", o->core_link, "time a cache line crossing between two cores against one kept on its core (the host's state for threads)");
    bench->add_flag("--dem", o->dem, "benchmark the DEM engine instead: the lift-and-spread phase of one settled scene under each law combination");
    bench->add_option("--scene", o->scene, "scene for --dem (default: data/scenes/small_wet.toml)");
    bench->add_option("--sizes", o->sizes, "with --dem: the size sweep, particle counts, e.g. 5e3,1e4,1e5,1e6 (the scene's cone scaled)");
    bench->add_option("--steps", o->size_steps, "with --sizes: steps S per timing unit, the same at every size (runs of S and 3 S steps, repeated until --timed particle-steps are timed)")
        ->capture_default_str();
    bench->add_option("--timed", o->size_timed, "with --sizes: particle-steps timed at least per size (pairs of runs repeated until reached)")
        ->capture_default_str()
        ->check(finite_positive);
    bench->add_option("--table", o->table, "tabulated model (default: data/bridge_table.csv)");
    bench->add_option("--format", o->format, "text | csv | markdown | json")->capture_default_str();

    return {{one, [o] { return run_bridge(*o); }},
            {gen, [o] { return run_bridge_table(*o); }},
            {err, [o] { return run_bridge_error(*o); }},
            {bench, [o] { return run_bench(*o); }}};
}

}  // namespace demscale::cli
