// Subcommands of the coarse-graining study: check-exponent (one k, a verdict and an exit code) and
// sweep (several k, the best per S_f). Both run the fine reference and the coarse runs side by
// side, reuse cached runs, and write a table and figures.
#include <optional>
#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "core/input_error.hpp"
#include "report/slump_study_files.hpp"
#include "report/slump_study_tables.hpp"
#include "report/similarity_table.hpp"

namespace demscale::cli {

namespace {

struct Options {
    std::string scene = default_scene;
    std::string exponents = "1";
    std::string sfs = "1.4,1.96,2.74,3.84";
    std::vector<std::string> scaled;
    std::optional<double> tol_slump, tol_spread, tol_profile;  // unset: the scene's [check]
    int jobs = 0, threads = 0;                                 // 0: from the machine
    int replicas = 1;
    std::string cache = default_cache;
    bool no_cache = false, no_png = false, force_dt = false;
    std::string out_dir = default_plots;
    std::string format = "text";
};

slump::StudyPlan plan_from(const Options& o, const std::string& exponent_field) {
    slump::StudyPlan plan;
    plan.fine = slump::load_slump_scene(o.scene);
    plan.exponents = parse_exponents(o.exponents, exponent_field);
    plan.scale_factors = parse_number_list(o.sfs, "--sf", 0, 100);
    plan.scaled = o.scaled;
    plan.tolerances = plan.fine.tolerances;
    auto tolerance = [](const std::optional<double>& given, double& target, const char* field) {
        if (!given) return;
        require_positive(*given, field);
        target = *given;
    };
    tolerance(o.tol_slump, plan.tolerances.slump, "--tol-slump");
    tolerance(o.tol_spread, plan.tolerances.spread, "--tol-spread");
    tolerance(o.tol_profile, plan.tolerances.profile, "--tol-profile");
    // Default: one run per core, one thread each (runs differ in cost; the fine one starts first).
    const auto par = parallelism(o.jobs, o.threads);
    plan.jobs = par.jobs, plan.threads_per_job = par.threads_per_job;
    if (!o.no_cache) plan.cache_dir = o.cache;
    plan.force_dt = o.force_dt;
    plan.replicas = o.replicas;
    return plan;
}

slump::Study run(const slump::StudyPlan& plan) {
    return slump::run_study(plan, [](const std::string& line) { std::cerr << "study: " << line << "\n"; });
}

// Prints the tables (text, markdown, csv or json) and the files written; returns the exit code.
int report(const Options& o, const slump::StudyPlan& plan, const slump::Study& study, const std::string& stem, bool gate) {
    const auto format = io::parse_format(o.format, "--format");
    const std::string label = display_path(o.scene);
    std::vector<io::Table> tables = {report::similarity_groups_table(plan.exponents), report::study_table(study, label)};
    if (plan.exponents.size() > 1) tables.push_back(report::best_exponent_table(study, plan.scale_factors));
    const auto files = report::write_study_files(study, label, o.out_dir, stem, !o.no_png);
    std::cout << join_tables(tables, format);
    const bool pass = study.all_within();
    if (format != io::Format::json && gate)
        std::cout << "\nverdict: " << (pass ? "PASS" : "FAIL") << " — "
                  << std::count_if(study.runs.begin(), study.runs.end(), [](const auto& r) { return r.within_tolerance; }) << " of "
                  << study.runs.size() << " coarse runs within tolerance\n";
    for (const auto& f : files.written) std::cerr << "wrote " << f.string() << "\n";
    return gate && !pass ? 1 : 0;
}

void add_common(CLI::App* c, Options& o) {
    c->add_option("--scene", o.scene, "scene TOML (default: data/scenes/kantro_wet.toml)");
    c->add_option("--sf", o.sfs, "scale factors S_f of the coarse runs")->capture_default_str();
    c->add_option("--scale", o.scaled, "parameters scaled by the basis k implies: gravity, youngs_modulus, velocity")
        ->delimiter(',');
    c->add_option("--tol-slump", o.tol_slump, "relative slump tolerance (default: the scene's [check])");
    c->add_option("--tol-spread", o.tol_spread, "relative spread-d95 tolerance (default: the scene's [check])");
    c->add_option("--tol-profile", o.tol_profile, "relative L2 profile tolerance (default: the scene's [check])");
    c->add_option("--replicas", o.replicas, "fine runs with other seeds, for the fine-vs-fine noise floor")->capture_default_str();
    c->add_option("--jobs", o.jobs, "runs side by side (default: one per core)");
    c->add_option("--threads", o.threads, "OpenMP threads per run (default: cores / jobs)");
    c->add_option("--cache", o.cache, "folder of finished runs, reused by scene key (default: cache/)");
    c->add_flag("--no-cache", o.no_cache, "run everything; read and write no cache");
    c->add_option("--out", o.out_dir, "folder for the table and figures (default: plots/)");
    c->add_option("--format", o.format, "text | markdown | csv | json")->capture_default_str();
    c->add_flag("--no-png", o.no_png, "no figures (gnuplot scripts only)");
    c->add_flag("--force-dt", o.force_dt, "accept a time step above 0.2 x the Rayleigh time");
}

}  // namespace

std::vector<Command> study_commands(CLI::App& app) {
    auto check = std::make_shared<Options>();
    auto* c = app.add_subcommand("check-exponent",
                                 "slump test of the coarse runs (gamma S_f^k) against the fine reference; exit 1 if any is out of tolerance");
    c->add_option("--exponent", check->exponents, "the candidate k")->required();
    add_common(c, *check);

    auto sweep = std::make_shared<Options>();
    sweep->exponents = "1,1.5,2,2.5,3";
    auto* s = app.add_subcommand("sweep", "check-exponent for several k: errors against k and against speed-up, best k per S_f");
    s->add_option("--exponents", sweep->exponents, "candidate exponents k")->capture_default_str();
    add_common(s, *sweep);

    return {{c,
             [check] {
                 const auto plan = plan_from(*check, "--exponent");
                 if (plan.exponents.size() != 1) throw InputError("--exponent", check->exponents, "one number (use sweep for several)");
                 const auto study = run(plan);
                 return report(*check, plan, study, "check_k" + format_short(plan.exponents.front()), true);
             }},
            {s, [sweep] {
                 const auto plan = plan_from(*sweep, "--exponents");
                 const auto study = run(plan);
                 return report(*sweep, plan, study, "sweep", false);
             }}};
}

}  // namespace demscale::cli
