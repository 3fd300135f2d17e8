#include "slump/liggghts_run.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "core/input_error.hpp"
#include "core/subprocess.hpp"
#include "dem/bridge_law.hpp"
#include "io/particle_state.hpp"
#include "io/pile_file.hpp"
#include "slump/liggghts_export.hpp"
#include "slump/measurements.hpp"
#include "slump/motion.hpp"

namespace demscale::slump {

namespace fs = std::filesystem;

namespace {

// The last lines of a program's output, for a message.
std::string tail(const std::string& text, int lines) {
    std::size_t at = text.size();
    for (int n = 0; n <= lines && at != std::string::npos && at > 0; ++n) at = text.rfind('\n', at - 1);
    return text.substr(at == std::string::npos ? 0 : at + 1);
}

// Whether `name` is an executable file in a folder of PATH.
bool on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    for (std::size_t start = 0; start <= dirs.size();) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (end > start && ::access(candidate.c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

// A folder of its own for one run, removed at the end when it was made here.
struct WorkDir {
    fs::path path;
    bool temporary = false;
    explicit WorkDir(const fs::path& given) : path(given), temporary(given.empty()) {
        if (temporary) path = fs::temp_directory_path() / ("demscale-liggghts-" + std::to_string(::getpid()) + "-" +
                                                           std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
        fs::create_directories(path);
    }
    ~WorkDir() {
        std::error_code ignored;
        if (temporary) fs::remove_all(path, ignored);
    }
    WorkDir(const WorkDir&) = delete;
    WorkDir& operator=(const WorkDir&) = delete;
};

}  // namespace

void use_liggghts(SlumpScene& s, int ranks, const std::string& ranks_field) {
    if (ranks < 1 || ranks > 64) throw InputError(ranks_field, std::to_string(ranks), "1 to 64 MPI ranks");
    if (s.wet && s.wet_walls)
        throw InputError(s.source + ": liquid.wet_walls", "true",
                         "false with --engine liggghts: LIGGGHTS' cohesion easo/capillary/viscous refuses walls, and a deck with dry "
                         "walls is another scene");
    if (s.wet) {
        const auto& source = dem::particle_curve_source(s);
        if (source.liggghts.empty())
            throw InputError(s.source + ": liquid.bridge_variant", std::string(source.value),
                             "a bridge LIGGGHTS has (mikami1998) with --engine liggghts: it has no equivalent of " + std::string(source.label));
    }
    s.liggghts_ranks = ranks;
}

SlumpResult run_by_liggghts(const SlumpScene& s, const std::function<void(const SlumpProgress&)>& progress, bool force_dt,
                            SlumpPhases phases) {
    if (!phases.resume.empty())
        throw InputError("--resume", phases.resume.string(), "a checkpoint of demscale's engine: a LIGGGHTS run starts again from its fill");
    if (phases.energy_ledger) throw InputError("--energy", "given", "demscale's engine only: LIGGGHTS books no energy ledger");
    for (const char* program : {"mpirun", "liggghts"})  // before the settle, which can take minutes
        if (!on_path(program))
            throw std::runtime_error(std::string(program) +
                                     " not found on PATH: --engine liggghts needs Open MPI and LIGGGHTS (Debian: apt-get install openmpi-bin liggghts)");
    // The fill: demscale's own pour and settle of the same scene and seed.
    SlumpScene here = s;
    here.liggghts_ranks = 0;
    const WorkDir dir(phases.work_dir);
    phases.settle_only = true;
    phases.checkpoint.clear();  // the settle is short; an interrupt restarts it
    SlumpResult res = run_slump(here, progress, force_dt, phases);
    const dem::Particles settled = res.final_state;
    export_liggghts(here, settled, dir.path, /*stop_at_rest=*/true);
    io::write_particle_state(dir.path / "settled.csv", settled);

    std::vector<std::string> argv = {"mpirun", "-np", std::to_string(s.liggghts_ranks), "--oversubscribe", "--bind-to", "none",
                                     "--mca", "btl_vader_single_copy_mechanism", "none"};
    if (::geteuid() == 0) argv.push_back("--allow-run-as-root");  // Open MPI refuses root without it
    for (const char* a : {"-wdir", dir.path.c_str(), "liggghts", "-in", "in.slump", "-log", "log.liggghts"}) argv.emplace_back(a);
    if (progress) progress({"liggghts", res.settle_end, res.settle_end + s.lift_height_m / s.lift_speed_m_per_s + s.spread_time_s,
                            res.steps, 0, {}});
    const auto start = std::chrono::steady_clock::now();
    const CommandOutput out = run_command(argv);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (out.exit_code != 0)
        throw std::runtime_error("LIGGGHTS under mpirun exited " + std::to_string(out.exit_code) + " in " + dir.path.string() + ":\n" +
                                 tail(out.output, 6));
    const auto dump = io::read_pile_file("LIGGGHTS' dump", (dir.path / "final.dump").string(), s.material.density);

    // The deck stops at rest and says at which step (LIGGGHTS counts from the lift's start); else it
    // ran the whole spread time.
    const auto steps = deck_steps(s);
    long ran = steps.lift + (steps.spread + steps.rest_check - 1) / steps.rest_check * steps.rest_check;
    const std::size_t said = out.output.rfind(liggghts_rest_line);
    res.came_to_rest = said != std::string::npos;
    if (res.came_to_rest) ran = std::stol(out.output.substr(said + std::string(liggghts_rest_line).size()));
    res.final_state = dump.particles;
    res.final = measure_pile(dump.particles, s);
    res.motion = summarize_motion(dump.particles, dump.particles.size(), s.rest_speed_m_per_s);
    res.lift_end = res.settle_end + static_cast<double>(steps.lift) * s.dt_s;
    res.end = res.settle_end + static_cast<double>(ran) * s.dt_s;
    // At rest over the five checks before it stopped: the window began four checks earlier.
    res.rest_since = res.came_to_rest ? res.end - static_cast<double>(4 * steps.rest_check) * s.dt_s : -1;
    res.steps += static_cast<std::size_t>(ran);
    res.wall_s += wall;
    return res;
}

}  // namespace demscale::slump
