// Subcommands of the slump test: slump (one run of a scene, optionally coarse-grained) and export liggghts.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <numeric>
#include <nlohmann/json.hpp>
#include <omp.h>
#include <unistd.h>

#include "cli_common.hpp"
#include "core/idle_cores.hpp"
#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "dem/law_parts.hpp"
#include "slump/liggghts_export.hpp"
#include "io/particle_state.hpp"
#include "io/vtk_writer.hpp"
#include "slump/coarse_grain.hpp"
#include "slump/scene_bridges.hpp"
#include "slump/slump_files.hpp"

namespace demscale::cli {

namespace {

struct Options {
    std::string scene = default_scene;
    double sf = 1, exponent = 1;
    std::vector<std::string> scaled;
    std::string format = "text";
    std::string out_dir = default_plots;
    double vtk_every = 0;
    int threads = 0;  // 0: the idle cores
    bool force_dt = false, no_png = false, fixed_time = false, energy = false;
    bool stop_at_rest = false;  // export liggghts: the deck stops the spread at rest
    std::string start;  // settled state to lift from
    std::string resume; // checkpoint of an interrupted run
    EngineOptions engine;
};

// --threads: N OpenMP threads; 0: OMP_NUM_THREADS when set, else the cores no other job is using
// (core/idle_cores.hpp), said on stderr when that is fewer than all.
void use_threads(int threads) {
    if (threads < 0) throw InputError("--threads", std::to_string(threads), ">= 1 (0: the idle cores)");
    if (threads > 0) {
        omp_set_num_threads(threads);
        return;
    }
    if (std::getenv("OMP_NUM_THREADS")) return;  // the user's (or CI's) own choice
    const int cores = omp_get_num_procs();
    const auto load = load_average();
    if (!load) return;
    const int idle = idle_cores(cores, *load);
    omp_set_num_threads(idle);
    if (idle < cores)
        std::fprintf(stderr, "note: %d of %d cores busy with other work (load %.2f): running on %d thread%s (--threads N to choose)\n",
                     cores - idle, cores, *load, idle, idle == 1 ? "" : "s");
}

// Progress on stderr: redrawn in place on a terminal, one line per phase otherwise.
std::function<void(const slump::SlumpProgress&)> slump_progress(io::VtkSeries* series, double vtk_every) {
    const bool tty = ::isatty(STDERR_FILENO);
    auto last_phase = std::make_shared<std::string>();
    auto next_frame = std::make_shared<double>(0.0);
    return [=](const slump::SlumpProgress& p) {
        if (series && p.state && p.time >= *next_frame) {
            series->add(p.time, p.state());
            *next_frame += vtk_every;
        }
        if (tty)
            std::fprintf(stderr, "\r%-7s t = %.3f s (phase ends by %.3f s), %zu steps, %.2e particle-steps/s   ", p.phase.c_str(),
                         p.time, p.phase_end, p.steps, p.particle_steps_per_s);
        else if (p.phase != *last_phase)
            std::fprintf(stderr, "slump: %s from t = %.3f s\n", p.phase.c_str(), p.time);
        *last_phase = p.phase;
    };
}

// Each size bin's share of the pile's mass, and the distribution's (slump/size_distribution.hpp).
nlohmann::ordered_json size_bins(const slump::SlumpScene& scene, const dem::Particles& pile) {
    const auto shares = slump::bin_mass_shares(scene.sizes);
    std::vector<double> mass(shares.size(), 0.0);
    for (std::size_t i = 0; i < pile.size(); ++i) mass[slump::size_bin(scene.sizes, pile.radius[i] / scene.radius_m)] += pile.mass[i];
    const double total = std::accumulate(mass.begin(), mass.end(), 0.0);
    for (auto& m : mass) m /= total;
    return {{"distribution_mass_fractions", shares}, {"pile_mass_fractions", mass}};
}

// The laws the scene chose, by their parts' choice values (dem/law_parts.hpp), and its bridge curves.
void add_laws(nlohmann::ordered_json& j, const slump::SlumpScene& scene) {
    j["contact_laws"] = nlohmann::ordered_json::array();
    for (const auto law : dem::chosen_laws(scene)) j["contact_laws"].push_back(std::string(law));
    j["bridge_law"] = scene.wet ? slump::bridge_variant_name(scene) : "none";  // liquid.bridge_variant
    j["wall_bridge_law"] = scene.wet && scene.wet_walls ? slump::wall_bridge_name(scene) : "none";  // liquid.wall_bridge
}

// The run's phases from --start (read into `settled`), --resume and --energy; its checkpoint and
// LIGGGHTS' deck, log and dump (--engine liggghts) go into --out.
slump::SlumpPhases slump_phases(const Options& o, dem::Particles& settled) {
    slump::SlumpPhases phases;
    if (!o.start.empty()) {
        settled = io::read_particle_state(o.start);
        phases.start = &settled;
    }
    phases.checkpoint = std::filesystem::path(o.out_dir) / "slump.ckpt";
    phases.work_dir = std::filesystem::path(o.out_dir) / "liggghts";
    phases.resume = o.resume;
    phases.energy_ledger = o.energy;
    return phases;
}

int run_slump_command(const Options& o) {
    const auto format = io::parse_format(o.format, "--format");
    use_threads(o.threads);
    std::vector<std::string> scene_warnings;
    const auto fine = load_scene(o.scene, &scene_warnings);
    auto scene = slump::coarse_grained(fine, {o.sf, o.exponent, o.scaled});
    apply_engine(scene, o.engine);
    if (o.fixed_time) scene.rest_duration_s = 1e30;  // run the full spread time (engine comparisons)
    std::unique_ptr<io::VtkSeries> series;
    if (o.vtk_every > 0) series = std::make_unique<io::VtkSeries>(std::filesystem::path(o.out_dir) / "slump_series.pvd");
    dem::Particles settled;
    const auto phases = slump_phases(o, settled);
    slump::SlumpResult r;
    try {
        r = slump::run_slump(scene, slump_progress(series.get(), o.vtk_every), o.force_dt, phases);
    } catch (const Interrupted& e) {
        throw Interrupted(std::string(e.what()) + "; continue with the same command and --resume " + e.checkpoint(), e.checkpoint());
    }
    if (!o.resume.empty() && std::filesystem::path(o.resume) == phases.checkpoint) std::filesystem::remove(phases.checkpoint);
    if (::isatty(STDERR_FILENO)) std::fprintf(stderr, "\n");
    char title[200];
    std::snprintf(title, sizeof title, "%s, S_f = %g, gamma = gamma0 S_f^%g: %zu spheres, slump %.1f mm, spread %.1f mm",
                  scene.name.c_str(), o.sf, o.exponent, r.particles, r.slump() * 1e3, r.final.spread * 1e3);
    const auto files = slump::write_slump_files(r, title, o.out_dir, "slump", !o.no_png);

    nlohmann::ordered_json j;
    j["scene"] = display_path(o.scene);
    j["sf"] = o.sf;
    j["exponent"] = o.exponent;
    j["particles"] = r.particles;
    j["floor"] = scene.rough_floor ? "rough" : "flat";
    j["steps"] = r.steps;
    j["pour_steps"] = r.pour_steps;
    j["dt_s"] = r.dt;
    j["critical_dt_s"] = r.critical_dt;
    j["wall_s"] = r.wall_s;
    j["particle_steps_per_s"] = r.particle_steps() / r.wall_s;  // pour included, as in wall_s
    // The thread governor's choice over the lift and spread (0 and 0 on one thread).
    j["thread_windows"] = {{"all_threads", r.windows_all_threads}, {"one_thread", r.windows_one_thread}};
    j["fill"] = scene.fill == slump::FillKind::poured ? "poured" : "lattice";
    j["particle_sizes"] = slump::describe(scene.sizes);
    if (!scene.sizes.monodisperse()) j["size_bins"] = size_bins(scene, r.final_state);
    add_laws(j, scene);
    j["pour_time_s"] = r.pour_time;
    j["fill_mass_g"] = r.fill.mass * 1e3;
    j["fill_mass_target_g"] = slump::fill_mass(scene) * 1e3;
    j["fill_height_mm"] = r.fill.height * 1e3;
    j["fill_solid_fraction"] = r.fill.solid_fraction;
    j["fill_core_fraction"] = r.fill.core_points > 0 ? nlohmann::ordered_json(r.fill.core_fraction) : nlohmann::ordered_json();
    j["fill_coordination"] = r.fill.coordination;
    j["fill_max_overlap_r"] = r.fill.max_overlap;
    j["settled"] = r.settled;
    j["came_to_rest"] = r.came_to_rest;
    j["time_to_rest_s"] = r.came_to_rest ? nlohmann::ordered_json(r.time_to_rest()) : nlohmann::ordered_json();
    j["end_speed_p50_m_per_s"] = r.motion.speed_p50;
    j["end_speed_p99_m_per_s"] = r.motion.speed_p99;
    j["end_speed_max_m_per_s"] = r.motion.speed_max;
    j["end_spin_p99_m_per_s"] = r.motion.spin_p99;
    j["end_moving"] = r.motion.moving;
    j["end_moving_at_edge"] = r.motion.moving_at_edge;
    j["initial_height_mm"] = r.initial_height * 1e3;
    j["final_height_mm"] = r.final.height * 1e3;
    j["slump_mm"] = r.slump() * 1e3;
    j["slump_over_fill_height"] = r.slump() / r.initial_height;
    j["slump_fine_radii"] = r.slump() / fine.radius_m;
    j["spread_mm"] = r.final.spread * 1e3;
    j["repose_angle_deg"] = r.final.repose_angle_deg ? nlohmann::ordered_json(*r.final.repose_angle_deg) : nlohmann::ordered_json();
    // The sphere-level measures the size-independent ones replace (docs/slump-measures.md).
    j["final_height_top_mm"] = r.final.height_top * 1e3;
    j["spread_d95_mm"] = r.final.spread_d95 * 1e3;
    j["spread_max_mm"] = r.final.spread_max * 1e3;
    j["end_time_s"] = r.end;
    if (r.energy_ledger && !r.history.empty()) {  // the energy ledger at the end (J) and how well it balanced
        const auto& e = r.history.back().energy;
        const auto& d = e.dissipated;
        j["energy_j"] = {{"kinetic", e.kinetic}, {"stored", e.stored.total()}, {"lost_normal_damping", d.normal_damping},
                         {"lost_friction", d.friction}, {"lost_rolling", d.rolling}, {"lost_bridges", d.bridge},
                         {"lost_spring_stiffness", d.spring_stiffness}, {"wall_work", e.wall_work}};
        j["energy_balance_error"] = r.energy_balance_error();
    }
    j["threads"] = omp_get_max_threads();
    const auto warnings = slump::geometry_warnings(scene, r.particles);
    j["warnings"] = warnings;
    j["bridge_warnings"] = scene_warnings;  // of the fine scene (V^ and theta are the coarse one's too), as printed at the start
    if (format == io::Format::json) {
        std::cout << j.dump(2) << "\n";
    } else {
        for (const auto& [k, v] : j.items())
            if (k != "warnings") std::cout << k << ": " << v.dump() << "\n";
        if (!r.came_to_rest) std::cout << "note: the pile had not come to rest by the end of the spread phase\n";
        for (const auto& w : warnings) std::cout << "warning: geometry limits similarity: " << w << "\n";
    }
    for (const auto& f : files) std::cerr << "wrote " << f.string() << "\n";
    return 0;
}

// Settles the scene's fill in demscale and writes it for LIGGGHTS (and as settled.csv for
// `demscale slump --start`), so both engines lift and spread the very same particles.
int run_export_liggghts(const Options& o) {
    use_threads(o.threads);
    // A coarse-grained scene exports as it runs: radius S_f R, surface tension gamma S_f^k, ...
    const auto scene = slump::coarse_grained(load_scene(o.scene), {o.sf, o.exponent, o.scaled});
    slump::SlumpPhases phases;
    phases.settle_only = true;
    const auto r = slump::run_slump(scene, slump_progress(nullptr, 0), o.force_dt, phases);
    const std::filesystem::path dir = o.out_dir;
    io::write_particle_state(dir / "settled.csv", r.final_state);
    for (const auto& f : slump::export_liggghts(scene, r.final_state, dir, o.stop_at_rest)) std::cout << "wrote " << f.string() << "\n";
    std::cout << "wrote " << (dir / "settled.csv").string() << "\n";
    if (scene.wet)
        std::cerr << "note: wet scene: bridges as LIGGGHTS' cohesion easo/capillary/viscous (between particles"
                  << (scene.wet_walls ? "; walls dry" : "") << "); the deck's header lists what differs\n";
    return 0;
}

}  // namespace

std::vector<Command> slump_commands(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* slump = app.add_subcommand("slump", "one mini-cone slump test (fill, settle, lift, spread), optionally coarse-grained");
    slump->add_option("--scene", o->scene, "scene TOML (default: data/scenes/kantro_wet.toml)");
    slump->add_option("--sf", o->sf, "scale factor S_f: particles of radius S_f R")->capture_default_str();
    slump->add_option("--exponent", o->exponent, "surface tension gamma S_f^k")->capture_default_str();
    slump->add_option("--scale", o->scaled, "parameters scaled by the basis k implies: gravity, youngs_modulus, velocity, viscosity")
        ->delimiter(',');
    slump->add_option("--format", o->format, "text | json")->capture_default_str();
    slump->add_option("--out", o->out_dir, "folder for CSV, VTK and the picture (default: plots/)");
    slump->add_option("--vtk-every", o->vtk_every, "also write a ParaView series every this many seconds (0: final state only)")
        ->check(finite_non_negative);
    slump->add_flag("--force-dt", o->force_dt, "accept a time step above 0.2 x the Rayleigh time");
    slump->add_flag("--no-png", o->no_png, "no side-view picture");
    slump->add_flag("--energy", o->energy,
                    "book the energy ledger (every loss, wall work, balance) into slump_history.csv; about 10 % slower");
    slump->add_option("--start", o->start, "lift and spread from this settled state (settled.csv of export liggghts)");
    slump->add_option("--resume", o->resume, "continue an interrupted run from its checkpoint (OUT/slump.ckpt)");
    slump->add_option("--threads", o->threads, "OpenMP threads (default: the cores no other job is using)");
    add_engine_options(slump, o->engine);
    slump->add_flag("--fixed-time", o->fixed_time, "run the whole spread time, no early stop at rest (engine comparisons)");

    auto* exp = app.add_subcommand("export", "write a scene for another DEM engine");
    auto* lig = exp->add_subcommand("liggghts", "settle the fill, then write a LIGGGHTS deck, data file and cone STL");
    lig->add_option("--scene", o->scene, "scene TOML (default: data/scenes/kantro_wet.toml)");
    lig->add_option("--out", o->out_dir, "output folder")->required();
    lig->add_option("--sf", o->sf, "scale factor S_f: export the coarse-grained scene")->capture_default_str();
    lig->add_option("--exponent", o->exponent, "surface tension gamma S_f^k of the coarse-grained scene")->capture_default_str();
    lig->add_option("--scale", o->scaled, "parameters scaled by the basis k implies: gravity, youngs_modulus, velocity, viscosity")
        ->delimiter(',');
    lig->add_option("--threads", o->threads, "OpenMP threads for the settling run (default: the idle cores)");
    lig->add_flag("--stop-at-rest", o->stop_at_rest, "the deck stops the spread once the pile is at rest by demscale's criterion "
                                                     "(default: the whole spread time, as benchmarks need)");
    exp->require_subcommand(1);

    return {{slump, [o] { return run_slump_command(*o); }},
            {lig, [o] { return run_export_liggghts(*o); }}};
}

}  // namespace demscale::cli
