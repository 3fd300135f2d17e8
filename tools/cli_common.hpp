// What every subcommand shares: default paths (shipped inputs; outputs in the working folder), input parsing helpers, and the
// Command shape (a CLI11 subcommand plus the function that runs it and returns the exit code).
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/table_config.hpp"
#include "io/table_format.hpp"
#include "slump/ensemble_verdict.hpp"
#include "slump/slump_scene.hpp"
#include "slump/slurm_backend.hpp"

namespace demscale::cli {

inline const std::string source_dir = DEMSCALE_SOURCE_DIR;
// The shipped inputs (table1.toml, scenes/, reference/, bridge_table.csv): the source tree's data/
// when it exists (a build tree), else the installed copy, <prefix>/share/demscale/data.
const std::string& data_dir();
inline std::string shipped(const std::string& relative) { return data_dir() + "/" + relative; }
inline const std::string default_config = shipped("table1.toml");
inline const std::string default_references = shipped("reference");
inline const std::string default_bridge_table = shipped("bridge_table.csv");
inline const std::string default_scene = shipped("scenes/kantro_wet.toml");
// Outputs go to the working folder, never into the source or install tree.
inline const std::string default_plots = "plots";
inline const std::string default_cache = "cache";  // finished slump runs, by scene key

struct Command {
    CLI::App* app;
    std::function<int()> run;
};

// Inputs named relative to the source tree when they live in it, so outputs carry no machine's paths.
io::TableConfig load_config(const std::string& path);
// The inputs of the similarity table and Figs. 3-4: a Table-1 configuration, those a scene implies,
// or both when they agree (else InputError listing the differing keys); neither: data/table1.toml.
io::TableConfig similarity_inputs(const std::string& config_path, const std::string& scene_path);
// A slump scene for a command that runs it, its bridge models' warnings printed on stderr
// (slump/bridge_warnings.hpp) and, when asked, handed back: every such command says when a fit is
// used outside its trust.
slump::SlumpScene load_scene(const std::string& path, std::vector<std::string>* bridge_warnings = nullptr);
std::string display_path(const std::string& path);

// Option checks that also refuse NaN and infinity (CLI11's own number checks let NaN through).
inline CLI::Validator finite_from_zero(bool zero_allowed) {
    const std::string range = zero_allowed ? "a finite number >= 0" : "a finite number > 0";
    return CLI::Validator(
        [=](std::string& s) {
            const double x = std::strtod(s.c_str(), nullptr);
            return std::isfinite(x) && (x > 0 || (zero_allowed && x == 0)) ? std::string() : "value " + s + "; accepted " + range;
        },
        zero_allowed ? "FINITE >= 0" : "FINITE > 0");
}
inline const CLI::Validator finite_positive = finite_from_zero(false);
inline const CLI::Validator finite_non_negative = finite_from_zero(true);

// "1,3" → {1, 3}; every item a number in (lo, hi). Throws InputError naming `field` and the range.
std::vector<double> parse_number_list(const std::string& text, const std::string& field, double lo, double hi);
// --sf as given, or, when empty, the S_f of Table 1 (1.4, 1.96, 2.74, 3.84) whose coarse scene the
// fine scene's cone does not limit (slump/coarse_grain.hpp); when it limits every one, those whose
// particles pass the top opening, so that the command says why each is limited.
std::vector<double> scale_factors_or_usable(const std::string& given, const slump::SlumpScene& fine);
// "LO,HI" and a level count → the log-spaced surface tension factors (slump::log_spaced_factors).
std::vector<double> parse_factor_range(const std::string& text, int levels, const std::string& range_field,
                                       const std::string& levels_field);
// Exponents k: numbers in (−20, 20).
std::vector<double> parse_exponents(const std::string& text, const std::string& field = "--exponent");

// Slump runs side by side: {jobs, threads per job}. 0 picks from the machine: one job per core,
// cores / jobs threads each. Throws InputError for negative values.
struct Parallelism {
    int jobs, threads_per_job;
};
Parallelism parallelism(int jobs, int threads);

// Where slump runs go: here (the default), or to Slurm as a job array (slump/slurm_backend.hpp).
struct SlurmOptions {
    std::string backend = "local";
    std::vector<std::string> sbatch_options;
    bool wait = false;
};
void add_backend_options(CLI::App* c, SlurmOptions& o);
// None for the local backend; InputError for an unknown backend, or Slurm options without it (the
// batch runner refuses Slurm without a cache).
std::optional<slump::SlurmSettings> slurm_settings(const SlurmOptions& o);

// Which engine lifts and spreads the fills: demscale's, or LIGGGHTS under mpirun (slump/liggghts_run.hpp).
struct EngineOptions {
    std::string engine = "demscale";
    int ranks = 0;  // 0: 2 with liggghts
};
void add_engine_options(CLI::App* c, EngineOptions& o);
// The scene made to run on the chosen engine; InputError for an unknown engine, --ranks without
// liggghts, or a scene LIGGGHTS cannot express (named keys), before anything runs.
void apply_engine(slump::SlumpScene& scene, const EngineOptions& o);
// parallelism() for that engine: with LIGGGHTS each run takes `ranks` cores, so unless --jobs is
// given, cores / ranks runs go side by side.
Parallelism parallelism(int jobs, int threads, const EngineOptions& engine);

// What every command that runs slump ensembles shares: how runs go side by side, the cache,
// where tables and figures go. add_study_run_options registers the options; batch_options turns
// them into the runner's settings.
struct StudyRunOptions {
    int jobs = 0, threads = 0;  // 0: from the machine
    std::string cache = default_cache;
    bool no_cache = false, no_png = false, force_dt = false;
    std::string out_dir = default_plots;
    std::string format = "text";
    std::string baseline = "dry";
    long seed_base = 0;  // 0: the scene's seed
    SlurmOptions slurm;
    EngineOptions engine;
};
void add_study_run_options(CLI::App* c, StudyRunOptions& o, const std::string& what_out);
// The runner's settings from the options; Parallelism from jobs and threads as parallelism() does.
struct BatchSettings {
    int jobs, threads_per_job;
    std::optional<std::string> cache_dir;
    bool force_dt;
    std::optional<slump::SlurmSettings> slurm;
};
BatchSettings batch_settings(const StudyRunOptions& o);
// --seed-base: the scene's first seed replaced (validated: 1 to 2^31 − 1), or left as it is for 0.
void apply_seed_base(slump::SlumpScene& scene, long seed_base);
// --baseline: "dry" (the dry control of the same seeds, which decides) or "none" (raw decides).
slump::Baseline parse_baseline(const std::string& text);

// Several tables in one output (a JSON array, or blocks separated by a blank line).
std::string join_tables(const std::vector<io::Table>& tables, io::Format format);

// Long jobs on stderr: `log` prints "<prefix>: line"; `live` redraws one line in place (the runs in
// progress) on a terminal and is empty otherwise, so that logs and pipes stay quiet.
struct ProgressOutput {
    std::function<void(const std::string&)> log, live;
};
ProgressOutput progress_output(const std::string& prefix);

// A progress line on stderr, redrawn in place on a terminal and printed once at the end otherwise.
std::function<void(int, int)> progress_printer(const std::string& what);

std::vector<Command> similarity_commands(CLI::App& app);  // table, curves, regress, scaling
std::vector<Command> bridge_commands(CLI::App& app);      // bridge, bridge-table, bridge-error
std::vector<Command> bench_commands(CLI::App& app);       // bench
std::vector<Command> slump_commands(CLI::App& app);       // slump, export liggghts
std::vector<Command> pile_commands(CLI::App& app);        // pile
std::vector<Command> study_commands(CLI::App& app);       // check-exponent, sweep
std::vector<Command> estimate_commands(CLI::App& app);    // estimate-exponent
std::vector<Command> report_commands(CLI::App& app);      // report
std::vector<Command> cluster_commands(CLI::App& app);     // cached-run (what a Slurm task runs)

}  // namespace demscale::cli
