// The bench subcommand: what things cost. Without flags, one bridge force evaluation of every model;
// --dem, the DEM engine's lift-and-spread phase under each law combination; --dem --sizes, the
// engine's rate as the work grows; --core-link, a cache line crossing two cores (the host's state,
// for the benchmark scripts' logs). Figures are printed, never judged (docs/performance.md).
#include <iostream>
#include <memory>

#include "bridge/bridge_cost.hpp"
#include "bridge/bridge_model.hpp"
#include "cli_common.hpp"
#include "core/core_link.hpp"
#include "core/idle_cores.hpp"
#include "core/input_error.hpp"
#include "io/bridge_table_file.hpp"
#include "slump/compiled_engines.hpp"
#include "slump/size_sweep.hpp"
#include "slump/slump_run.hpp"
#include <omp.h>

namespace demscale::cli {

namespace {

struct Options {
    std::string format = "text";
    std::string table = default_bridge_table;
    bool dem = false, core_link = false;
    std::string scene = shipped("scenes/small_wet.toml");
    double seconds = 0.2;
    std::string sizes;        // --dem --sizes: the size sweep
    int size_steps = 100;     // the same at every size
    double size_timed = 1e7;  // particle-steps timed at least per size
};

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
            t.rows.push_back({slump::laws_label(s) + rolling + dashpot + (combinations[n].ledger ? " +energy ledger" : ""),
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
    // The engine's own memory by consumer at the largest size, lattice order: where the bytes go.
    io::Table memory;
    memory.title = "The engine's memory by consumer at the largest size (lattice order, the end of the last run)";
    memory.metadata = {{"bytes", "what each consumer's containers hold (their capacities) over the particles; the process's peak "
                                 "(peak_bytes_per_particle above) adds the fill, the copies a run returns and the allocator's slack"}};
    memory.columns = {"consumer", "laws", "particles", "bytes_per_particle", "share_pct"};
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
                t.rows.push_back({slump::laws_label(s), shuffled ? "shuffled" : "lattice", double(point.particles),
                                  double(point.steps), timed ? io::Cell(point.wall_s) : untimed,
                                  timed ? io::Cell(point.particle_steps_per_s) : untimed,
                                  timed ? io::Cell(point.particle_steps_per_s / smallest) : untimed, point.contacts_per_particle,
                                  per_contact ? io::Cell(point.contact_steps_per_s) : none,
                                  per_contact ? io::Cell(point.contact_steps_per_s / smallest_per_contact) : none,
                                  point.peak_bytes_per_particle > 0 ? io::Cell(point.peak_bytes_per_particle) : io::Cell(std::string("-"))});
                if (!shuffled && n == sizes.back()) {
                    double total = 0;
                    for (const auto& item : point.engine_memory) total += static_cast<double>(item.bytes);
                    for (const auto& item : point.engine_memory)
                        memory.rows.push_back({item.name, slump::laws_label(s), double(point.particles),
                                               static_cast<double>(item.bytes) / static_cast<double>(point.particles),
                                               total > 0 ? 100 * static_cast<double>(item.bytes) / total : 0.0});
                    memory.rows.push_back({std::string("all"), slump::laws_label(s), double(point.particles),
                                           total / static_cast<double>(point.particles), 100.0});
                }
            }
        }
    std::cout << join_tables({t, memory}, io::parse_format(o.format, "--format"));
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

std::vector<Command> bench_commands(CLI::App& app) {
    auto o = std::make_shared<Options>();
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

    return {{bench, [o] { return run_bench(*o); }}};
}

}  // namespace demscale::cli
