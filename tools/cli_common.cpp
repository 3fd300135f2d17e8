#include "cli_common.hpp"

#include "slump/coarse_grain.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>
#include <unistd.h>

#include "core/input_error.hpp"
#include "slump/bridge_warnings.hpp"
#include "slump/liggghts_run.hpp"
#include "slump/response_study.hpp"
#include "slump/scene_similarity.hpp"

namespace demscale::cli {

const std::string& data_dir() {
    static const std::string dir = [] {
        const std::string in_source = source_dir + "/data";
        return std::filesystem::is_directory(in_source) ? in_source : std::string(DEMSCALE_INSTALLED_DATA_DIR);
    }();
    return dir;
}

// Shipped inputs are shown as data/…, wherever they live.
std::string display_path(const std::string& path) {
    const std::string root = std::filesystem::path(data_dir()).parent_path().string() + "/";
    return path.rfind(root, 0) == 0 ? path.substr(root.size()) : path;
}

void add_study_run_options(CLI::App* c, StudyRunOptions& o, const std::string& what_out) {
    c->add_option("--jobs", o.jobs, "runs side by side (default: one per core)");
    c->add_option("--threads", o.threads, "OpenMP threads per run (default: cores / jobs)");
    c->add_option("--cache", o.cache, "folder of finished runs, reused by scene key (default: cache/)");
    c->add_flag("--no-cache", o.no_cache, "run everything; read and write no cache");
    c->add_option("--out", o.out_dir, "folder for " + what_out + " (default: plots/)");
    c->add_option("--format", o.format, "text | markdown | csv | json")->capture_default_str();
    c->add_flag("--no-png", o.no_png, "no figures (gnuplot scripts only)");
    c->add_flag("--force-dt", o.force_dt, "accept a time step above 0.2 x the Rayleigh time");
    c->add_option("--baseline", o.baseline,
                  "dry: also run the scene without liquid (same seeds) and judge after removing its coarse - fine offset; none: raw only")
        ->capture_default_str();
    c->add_option("--seed-base", o.seed_base, "first seed of every ensemble (default: the scene's `seed`); another base draws new piles");
    add_backend_options(c, o.slurm);
    add_engine_options(c, o.engine);
}

void add_engine_options(CLI::App* c, EngineOptions& o) {
    c->add_option("--engine", o.engine, "what lifts and spreads the fills: demscale, or liggghts (LIGGGHTS under mpirun; the fill is settled here)")
        ->capture_default_str();
    c->add_option("--ranks", o.ranks, "with --engine liggghts: MPI ranks per run (default 2)");
}

void apply_engine(slump::SlumpScene& scene, const EngineOptions& o) {
    if (o.engine == "demscale") {
        if (o.ranks != 0) throw InputError("--ranks", std::to_string(o.ranks), "only with --engine liggghts");
        return;
    }
    if (o.engine != "liggghts") throw InputError("--engine", o.engine, "demscale or liggghts");
    slump::use_liggghts(scene, o.ranks == 0 ? 2 : o.ranks, "--ranks");
}

void apply_seed_base(slump::SlumpScene& scene, long seed_base) {
    if (seed_base == 0) return;
    if (seed_base < 1 || seed_base > 2147483647L) throw InputError("--seed-base", std::to_string(seed_base), "1 to 2147483647");
    scene.seed = static_cast<unsigned>(seed_base);
}

slump::Baseline parse_baseline(const std::string& text) {
    if (text == "dry") return slump::Baseline::dry;
    if (text == "none") return slump::Baseline::none;
    throw InputError("--baseline", text, "dry (a dry control of the same seeds decides) or none (the raw comparison decides)");
}

void add_backend_options(CLI::App* c, SlurmOptions& o) {
    c->add_option("--backend", o.backend, "where the slump runs go: local, or slurm (a job array; run again to collect)")
        ->capture_default_str();
    c->add_option("--sbatch-option", o.sbatch_options, "with --backend slurm: an #SBATCH line, e.g. --sbatch-option=--partition=short")
        ->allow_extra_args(false);
    c->add_flag("--wait", o.wait, "with --backend slurm: wait for the runs and go on, instead of exiting 5 until they are done");
}

std::optional<slump::SlurmSettings> slurm_settings(const SlurmOptions& o) {
    if (o.backend == "local") {
        if (!o.sbatch_options.empty() || o.wait) throw InputError("--backend", "local", "slurm, with --sbatch-option or --wait");
        return std::nullopt;
    }
    if (o.backend != "slurm") throw InputError("--backend", o.backend, "local or slurm");
    slump::SlurmSettings s;
    s.executable = std::filesystem::read_symlink("/proc/self/exe");  // the tasks run this very build
    s.sbatch_options = o.sbatch_options;
    s.wait = o.wait;
    return s;
}

Parallelism parallelism(int jobs, int threads, const EngineOptions& engine) {
    auto par = parallelism(jobs, threads);
    if (engine.engine == "liggghts" && jobs == 0) {  // each run takes `ranks` cores: fewer side by side
        const int ranks = engine.ranks == 0 ? 2 : engine.ranks, cores = par.jobs * par.threads_per_job;
        par.jobs = std::max(1, cores / ranks);
        par.threads_per_job = std::max(1, cores / par.jobs);
    }
    return par;
}

BatchSettings batch_settings(const StudyRunOptions& o) {
    const auto par = parallelism(o.jobs, o.threads, o.engine);
    return {par.jobs, par.threads_per_job, o.no_cache ? std::nullopt : std::optional<std::string>(o.cache), o.force_dt,
            slurm_settings(o.slurm)};
}

io::TableConfig load_config(const std::string& path) {
    auto c = io::load_table_config(path);
    c.source = display_path(c.source);
    return c;
}

slump::SlumpScene load_scene(const std::string& path, std::vector<std::string>* bridge_warnings) {
    auto scene = slump::load_slump_scene(path);
    const auto warnings = slump::bridge_warnings(scene);
    for (const auto& w : warnings) std::cerr << "warning: " << w << "\n";
    if (bridge_warnings) *bridge_warnings = warnings;
    return scene;
}

io::TableConfig similarity_inputs(const std::string& config_path, const std::string& scene_path) {
    if (scene_path.empty()) return load_config(config_path.empty() ? default_config : config_path);
    const auto scene = slump::load_slump_scene(scene_path);
    if (!config_path.empty()) {
        const auto config = load_config(config_path);
        const auto differences = slump::differing_inputs(config, scene);
        if (differences.empty()) return config;
        std::string list;
        for (const auto& d : differences) list += "\n  " + d;
        throw InputError("--scene " + scene_path, std::to_string(differences.size()) + " input(s) differing from --config " +
                                                      config_path + ":" + list + "\n",
                         "the same particle, liquid and bridge in both, or only one of them");
    }
    auto c = slump::similarity_inputs(scene);
    c.source = display_path(c.source);
    return c;
}

std::vector<double> parse_number_list(const std::string& text, const std::string& field, double lo, double hi) {
    std::vector<double> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, end - start);
        char* stop = nullptr;
        const double k = std::strtod(item.c_str(), &stop);
        if (item.empty() || stop != item.c_str() + item.size() || !(k > lo && k < hi))
            throw InputError(field, "\"" + item + "\"",
                             "comma-separated numbers in (" + format_number(lo) + ", " + format_number(hi) + "), e.g. 1,3");
        out.push_back(k);
        start = end + 1;
    }
    return out;
}

std::vector<double> parse_exponents(const std::string& text, const std::string& field) {
    return parse_number_list(text, field, -20, 20);
}

std::vector<double> parse_factor_range(const std::string& text, int levels, const std::string& range_field,
                                       const std::string& levels_field) {
    const auto range = parse_number_list(text, range_field, 0, 1e6);
    if (range.size() != 2) throw InputError(range_field, text, "two surface tension factors LO,HI with 0 < LO < HI (e.g. 0.5,4)");
    return slump::log_spaced_factors(range[0], range[1], levels, range_field, levels_field);
}

Parallelism parallelism(int jobs, int threads) {
    if (jobs < 0) throw InputError("--jobs", std::to_string(jobs), ">= 1 (0: one per core)");
    if (threads < 0) throw InputError("--threads", std::to_string(threads), ">= 1 (0: cores / jobs)");
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int j = jobs > 0 ? jobs : cores;
    return {j, threads > 0 ? threads : std::max(1, cores / j)};
}

std::string join_tables(const std::vector<io::Table>& tables, io::Format format) {
    if (format == io::Format::json) {
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const auto& t : tables) all.push_back(nlohmann::ordered_json::parse(io::render(t, format)));
        return all.dump(2) + "\n";
    }
    std::string s;
    for (const auto& t : tables) s += (s.empty() ? "" : "\n") + io::render(t, format);
    return s;
}

ProgressOutput progress_output(const std::string& prefix) {
    ProgressOutput out;
    const bool tty = ::isatty(STDERR_FILENO);
    out.log = [prefix, tty](const std::string& line) {
        std::fprintf(stderr, "%s%s: %s\n", tty ? "\r\033[K" : "", prefix.c_str(), line.c_str());
    };
    if (tty)
        out.live = [](const std::string& line) {
            constexpr std::size_t width = 150;  // one terminal line; longer lines would scroll instead of redrawing
            std::fprintf(stderr, "\r\033[K%s", line.size() > width ? (line.substr(0, width - 3) + "...").c_str() : line.c_str());
            std::fflush(stderr);
        };
    return out;
}

std::function<void(int, int)> progress_printer(const std::string& what) {
    const bool tty = ::isatty(STDERR_FILENO);
    return [what, tty](int done, int total) {
        if (tty) std::fprintf(stderr, "\r%s: %d/%d (%3.0f%%)%s", what.c_str(), done, total, 100.0 * done / total,
                              done == total ? "\n" : "");
        else if (done == total) std::fprintf(stderr, "%s: %d/%d done\n", what.c_str(), done, total);
    };
}

std::vector<double> scale_factors_or_usable(const std::string& given, const slump::SlumpScene& fine) {
    if (!given.empty()) return parse_number_list(given, "--sf", 0, 100);
    const auto usable = slump::usable_scale_factors(fine, slump::table1_scale_factors);
    if (!usable.empty()) return usable;
    std::vector<double> passing;  // none usable: those the study can name as geometry-limited
    for (double sf : slump::table1_scale_factors)
        if (slump::passes_opening(fine, sf)) passing.push_back(sf);
    return passing;
}

}  // namespace demscale::cli
