// Subcommands of the coarse-graining study: check-exponent (one k, a verdict and an exit code) and
// sweep (several k, the best per S_f). Both run the fine reference and the coarse runs side by
// side, reuse cached runs, and write a table and figures.
#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "report/exponent_estimate_files.hpp"
#include "core/input_error.hpp"
#include "report/slump_study_files.hpp"
#include "report/slump_study_tables.hpp"
#include "report/similarity_table.hpp"
#include "io/atomic_file.hpp"
#include "slump/runs_verdict.hpp"
#include "stats/verdict.hpp"

namespace demscale::cli {

namespace {

struct Options {
    std::string scene = default_scene;
    std::string exponents = "1";
    std::string sfs;  // empty: the scene's usable S_f of Table 1's
    std::vector<std::string> scaled;
    std::optional<double> tol_slump, tol_spread, tol_profile;  // unset: the scene's [check]
    int seeds = 8;
    bool k_range = false;
    std::string runs;  // check-exponent: a runs file to judge instead of running
    StudyRunOptions run;
};

slump::StudyPlan plan_from(const Options& o, const std::string& exponent_field) {
    slump::StudyPlan plan;
    plan.fine = load_scene(o.scene);
    apply_seed_base(plan.fine, o.run.seed_base);
    apply_engine(plan.fine, o.run.engine);
    plan.exponents = parse_exponents(o.exponents, exponent_field);
    plan.scale_factors = scale_factors_or_usable(o.sfs, plan.fine);
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
    const auto b = batch_settings(o.run);
    plan.jobs = b.jobs, plan.threads_per_job = b.threads_per_job, plan.force_dt = b.force_dt;
    if (b.cache_dir) plan.cache_dir = *b.cache_dir;
    plan.slurm = b.slurm;
    plan.seeds = o.seeds;
    plan.baseline = parse_baseline(o.run.baseline);
    return plan;
}

slump::Study run(slump::StudyPlan plan) {
    const auto out = progress_output("study");
    plan.live = out.live;
    return slump::run_study(plan, out.log);
}

// PASS, INCONCLUSIVE and FAIL among the judged ensembles (the unusable left out), in Verdict's order.
std::array<std::size_t, 3> verdict_counts(const std::vector<slump::EnsembleVerdict>& deciding) {
    std::array<std::size_t, 3> n{};
    for (const auto& v : deciding)
        if (v.unusable.empty()) ++n[static_cast<std::size_t>(v.overall)];
    return n;
}

// "2 PASS, 0 FAIL, 1 INCONCLUSIVE of 3"
std::string count_text(const std::array<std::size_t, 3>& n) {
    return std::to_string(n[0]) + " PASS, " + std::to_string(n[2]) + " FAIL, " + std::to_string(n[1]) + " INCONCLUSIVE of " +
           std::to_string(n[0] + n[1] + n[2]);
}

// Prints the tables (text, markdown, csv or json) and the files written; returns the exit code:
// with gate, 0 PASS, 1 FAIL, 4 INCONCLUSIVE (the verdict of every ensemble together).
int report(const Options& o, const slump::StudyPlan& plan, const slump::Study& study, const std::string& stem, bool gate) {
    const auto format = io::parse_format(o.run.format, "--format");
    const std::string label = display_path(o.scene);
    std::vector<io::Table> tables = {report::verdict_table(study, label), report::ensemble_table(study, label),
                                     report::similarity_groups_table(plan.exponents)};
    if (plan.exponents.size() > 1) tables.push_back(report::best_exponent_table(study, study.judged_scale_factors()));
    const auto files = report::write_study_files(study, label, o.run.out_dir, stem, !o.run.no_png);
    const auto overall = study.overall();
    if (format == io::Format::json) {
        // One object: the overall verdict, then the tables (arrays of rows keyed by column).
        auto j = nlohmann::ordered_json::parse(join_tables(tables, format));
        nlohmann::ordered_json out;
        out["verdict"] = stats::verdict_name(overall);
        out["tables"] = j;
        std::cout << out.dump(2) << "\n";
    } else {
        std::cout << join_tables(tables, format);
    }
    if (format != io::Format::json && gate) {
        const auto n = verdict_counts(study.deciding());
        std::cout << "\nverdict: " << stats::verdict_name(overall) << " — " << count_text(n) << " judged (S_f, k) ensembles of " << plan.seeds << " seeds"
                  << (study.has_control() ? ", baseline-corrected" : "") << "\n";
        for (const auto& l : study.limited) {
            std::cout << "S_f = " << format_short(l.sf) << ": GEOMETRY-LIMITED, not run (";
            for (std::size_t i = 0; i < l.reasons.size(); ++i) std::cout << (i ? "; " : "") << l.reasons[i];
            std::cout << "); it does not enter the verdict\n";
        }
        // The cost: distinct runs (equal scenes run once), how many came from the cache, the wall time.
        std::set<std::string> distinct, cached, dry;
        for (const auto* r : study.all_runs()) {
            distinct.insert(r->key);
            if (r->from_cache) cached.insert(r->key);
            if (plan.fine.wet && !r->scene.wet) dry.insert(r->key);
        }
        std::cout << "cost: " << distinct.size() << " distinct runs (" << cached.size() << " from the cache"
                  << (study.has_control() ? "; " + std::to_string(dry.size()) + " of them the dry control" : std::string()) << "), "
                  << format_short(study.wall_s, 3) << " s of wall time, " << plan.jobs << " job(s) x " << plan.threads_per_job
                  << " thread(s)"
                  << (plan.fine.liggghts_ranks > 0 ? "; lifted and spread by LIGGGHTS on " + std::to_string(plan.fine.liggghts_ranks) +
                                                         " MPI ranks (fills settled by demscale)"
                                                   : std::string())
                  << "\n";
        if (study.second_look.any()) std::cout << study.second_look.describe() << "\n";
        for (const auto& v : study.deciding())
            if (!v.unusable.empty())
                std::cout << "S_f = " << format_short(v.sf) << ", k = " << format_short(v.exponent) << ": UNUSABLE FILL, not judged ("
                          << v.unusable << "); it does not enter the verdict\n";
        if (n[2] > 0 && overall != stats::Verdict::fail)
            std::cout << "no FAIL holds for the family: " << n[2] << (n[2] == 1 ? " ensemble FAILs" : " ensembles FAIL")
                      << " on its own, but no criterion's interval stays outside its tolerance at 5 % / " << study.family_size()
                      << " (Holm, the " << study.family_size() << " criteria x S_f judged; docs/verdicts.md)\n";
        if (study.judged_scale_factors().empty())
            std::cout << "INCONCLUSIVE: no S_f could be judged in this scene's cone (a finer scene, lower [check] limits, or fills "
                         "the cone can hold)\n";
        else if (overall == stats::Verdict::inconclusive)
            std::cout << "INCONCLUSIVE: the 95 % intervals straddle a tolerance; the smallest tolerances these data confirm are in the "
                         "verdict table (more --seeds narrow the intervals)\n";
    }
    for (const auto& f : files.written) std::cerr << "wrote " << f.string() << "\n";
    if (!gate) return 0;
    return overall == stats::Verdict::pass ? 0 : overall == stats::Verdict::fail ? 1 : 4;
}

// --k-range: estimate-exponent's response curves (its default design) beside the verdicts, and from
// them k-hat and the range of k whose slump passes, per judged S_f and jointly.
void print_k_range(const Options& o, const slump::StudyPlan& plan, const slump::Study& study) {
    if (!plan.fine.wet || study.judged_scale_factors().empty()) {
        std::cout << "range of k: none to measure (" << (plan.fine.wet ? "no S_f could be judged" : "a dry scene has no cohesion to vary") << ")\n";
        return;
    }
    slump::ResponsePlan rp;
    rp.fine = plan.fine;
    rp.fine.tolerances = plan.tolerances;
    rp.scale_factors = study.judged_scale_factors();
    rp.baseline = plan.baseline;
    rp.batch.jobs = plan.jobs, rp.batch.threads_per_job = plan.threads_per_job, rp.batch.force_dt = plan.force_dt;
    rp.batch.cache_dir = plan.cache_dir, rp.batch.slurm = plan.slurm;
    const auto out = progress_output("k-range");
    rp.batch.live = out.live;
    const auto est = slump::run_response_study(rp, out.log);
    const auto files = report::write_estimate_files(est, display_path(o.scene), o.run.out_dir, !o.run.no_png);
    std::cout << "\nk-hat and the range of k that passes the slump tolerance (transition model on estimate-exponent's response curves, "
              << est.fits.size() << (est.fits.size() == 1 ? " fit" : " fits") << "; docs/exponent-estimate.md):\n";
    for (std::size_t i = 0; i < est.fits.size(); ++i)
        std::cout << "  " << report::describe_fit(est.fits[i], &est.passing[i], plan.tolerances.slump) << "\n";
    for (const auto& f : files.written) std::cerr << "wrote " << f.string() << "\n";
}

// check-exponent --runs: the verdict on a runs file, slump and spread (such a file holds no profiles);
// nothing runs. Exit codes as for the runs themselves.
int check_runs_file(const Options& o) {
    if (o.k_range) throw InputError("--k-range", "given with --runs", "without --runs (estimate-exponent --runs FILE judges the response curves)");
    const auto plan = plan_from(o, "--exponent");
    if (plan.exponents.size() != 1) throw InputError("--exponent", o.exponents, "one number");
    const auto format = io::parse_format(o.run.format, "--format");
    const auto rows = slump::read_runs_file(o.runs, plan.fine.liquid.surface_tension_n_per_m);
    const auto verdicts = slump::judge_runs(rows, display_path(o.runs), plan.fine.liquid.surface_tension_n_per_m, plan.exponents.front(),
                                            o.sfs.empty() ? std::vector<double>{} : plan.scale_factors, plan.tolerances, plan.baseline);
    const std::string label = display_path(o.scene);
    const auto table = report::verdict_table(verdicts, label, display_path(o.runs));
    const auto path = std::filesystem::path(o.run.out_dir) / ("check_k" + format_short(plan.exponents.front()) + "_from_runs.csv");
    io::write_file_atomically(path, io::render(table, io::Format::csv));
    const auto overall = verdicts.overall();
    if (format == io::Format::json) {
        nlohmann::ordered_json out;
        out["verdict"] = stats::verdict_name(overall);
        out["tables"] = nlohmann::ordered_json::parse(join_tables({table}, format));
        std::cout << out.dump(2) << "\n";
    } else {
        std::cout << join_tables({table}, format);
        std::cout << "\nruns read from " << display_path(o.runs) << " (none run; slump and spread judged, the profile not: no profiles in a runs file)\n"
                  << "verdict: " << stats::verdict_name(overall) << " — " << count_text(verdict_counts(verdicts.deciding())) << " judged S_f" << (verdicts.has_control() ? ", baseline-corrected" : ", raw") << "\n";
    }
    std::cerr << "wrote " << path.string() << "\n";
    return overall == stats::Verdict::pass ? 0 : overall == stats::Verdict::fail ? 1 : 4;
}

void add_common(CLI::App* c, Options& o) {
    c->add_option("--scene", o.scene, "scene TOML (default: data/scenes/kantro_wet.toml)");
    c->add_option("--sf", o.sfs,
                  "scale factors S_f of the coarse runs (default: those of 1.4,1.96,2.74,3.84 the scene's cone does not limit)");
    c->add_option("--scale", o.scaled, "parameters scaled by the basis k implies: gravity, youngs_modulus, velocity, viscosity")
        ->delimiter(',');
    c->add_option("--tol-slump", o.tol_slump, "slump tolerance, a fraction of the fill height (default: the scene's [check])");
    c->add_option("--tol-spread", o.tol_spread, "relative spread tolerance (diameter at half height) (default: the scene's [check])");
    c->add_option("--tol-profile", o.tol_profile, "profile tolerance, relative L2 shape distance (default: the scene's [check])");
    c->add_option("--seeds", o.seeds, "runs per ensemble: the fine one and each (S_f, k)")->capture_default_str();
    c->add_flag("--k-range", o.k_range,
                "also run estimate-exponent's response curves (its default design, cached and shared) and print k-hat with its interval "
                "and the range of k that passes, per S_f and jointly");
    add_study_run_options(c, o.run, "the table and figures");
}

}  // namespace

std::vector<Command> study_commands(CLI::App& app) {
    auto check = std::make_shared<Options>();
    auto* c = app.add_subcommand("check-exponent",
                                 "slump test of coarse ensembles (gamma S_f^k) against the fine ensemble; exit 0 PASS, 1 FAIL, 4 INCONCLUSIVE");
    c->add_option("--exponent", check->exponents, "the candidate k")->required();
    c->add_option("--runs", check->runs,
                  "judge the runs in this CSV instead of running (docs/file-formats.md, runs file; slump and spread only: "
                  "a runs file holds no profiles)");
    add_common(c, *check);

    auto sweep = std::make_shared<Options>();
    sweep->exponents = "1,1.5,2,2.5,3";
    auto* s = app.add_subcommand("sweep", "check-exponent for several k: errors against k and against speed-up, best k per S_f");
    s->add_option("--exponent,--exponents", sweep->exponents, "candidate exponents k, comma-separated")->capture_default_str();
    add_common(s, *sweep);

    return {{c,
             [check] {
                 if (!check->runs.empty()) return check_runs_file(*check);
                 const auto plan = plan_from(*check, "--exponent");
                 if (plan.exponents.size() != 1) throw InputError("--exponent", check->exponents, "one number (use sweep for several)");
                 const auto study = run(plan);
                 const int code = report(*check, plan, study, "check_k" + format_short(plan.exponents.front()), true);
                 if (check->k_range) print_k_range(*check, plan, study);
                 return code;
             }},
            {s, [sweep] {
                 const auto plan = plan_from(*sweep, "--exponents");
                 const auto study = run(plan);
                 const int code = report(*sweep, plan, study, "sweep", false);
                 if (sweep->k_range) print_k_range(*sweep, plan, study);
                 return code;
             }}};
}

}  // namespace demscale::cli
