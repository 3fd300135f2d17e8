// Subcommand estimate-exponent: response curves of the slump test to surface tension, fine and
// coarse, and the exponent k̂ measured from their shift, with its 95 % interval. On a dry scene:
// the dry control (coarse against fine, no liquid). Runs are cached and resumable like check-exponent's.
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "core/input_error.hpp"
#include "report/exponent_estimate_files.hpp"

namespace demscale::cli {

namespace {

struct Options {
    std::string scene = default_scene;
    std::string sfs = "1.4,1.96";
    std::string range = "0.5,1.6";  // below the reference scene's stand/slump transition (docs/exponent-estimate.md, "The design")
    int levels = 5, seeds = 4, resamples = 1000;
    double stands_below = stats::TransitionSettings{}.stands_below;
    double offset = 1;
    std::string runs;  // a runs file to judge instead of running
    StudyRunOptions run;
};

slump::ResponsePlan plan_from(const Options& o) {
    slump::ResponsePlan plan;
    plan.fine = load_scene(o.scene);
    apply_seed_base(plan.fine, o.run.seed_base);
    apply_engine(plan.fine, o.run.engine);
    plan.scale_factors = parse_number_list(o.sfs, "--sf", 0, 100);
    plan.factors = parse_factor_range(o.range, o.levels, "--range", "--levels");
    plan.offset_exponent = o.offset;
    plan.seeds = o.seeds;
    plan.baseline = parse_baseline(o.run.baseline);
    if (o.resamples < 100 || o.resamples > 100000) throw InputError("--resamples", std::to_string(o.resamples), "100 to 100000");
    plan.search.resamples = o.resamples;
    if (!(o.stands_below > 0 && o.stands_below < 1)) throw InputError("--stands-below", format_number(o.stands_below), "between 0 and 1 (a share of the fill height)");
    plan.transition.stands_below = o.stands_below;
    const auto b = batch_settings(o.run);
    plan.batch.jobs = b.jobs, plan.batch.threads_per_job = b.threads_per_job, plan.batch.force_dt = b.force_dt;
    if (b.cache_dir) plan.batch.cache_dir = *b.cache_dir;
    plan.batch.slurm = b.slurm;
    return plan;
}

std::string sf_name(double sf) { return sf == 0 ? "all S_f" : "S_f = " + format_short(sf, 3); }

std::string interval_text(const stats::Interval& i) { return "[" + format_short(i.low, 3) + ", " + format_short(i.high, 3) + "]"; }

std::string shift_summary(const stats::ExponentEstimate& e) {
    std::string s = sf_name(e.sf) + ": k-hat = " + format_short(e.k, 3) + " " + interval_text(e.ci);
    if (!e.determined) return s + " undetermined";
    if (e.split_levels > 0) s += " (rests on " + std::to_string(e.split_levels) + " split " + (e.split_levels == 1 ? "level" : "levels") + ")";
    return s;
}

int run_estimate(const Options& o) {
    auto plan = plan_from(o);
    const auto out = progress_output("estimate");
    plan.batch.live = out.live;
    const auto study = o.runs.empty() ? slump::run_response_study(plan, out.log)
                                      : slump::response_study_from_runs(slump::read_runs_file(o.runs, plan.fine.liquid.surface_tension_n_per_m),
                                                                        plan, display_path(o.runs));
    const auto format = io::parse_format(o.run.format, "--format");
    const std::string label = display_path(o.scene);
    std::vector<io::Table> tables = {report::response_table(study, label)};
    tables.push_back(study.wet ? report::exponent_estimate_table(study, label) : report::dry_baseline_table(study, label));
    const auto files = report::write_estimate_files(study, label, o.run.out_dir, !o.run.no_png);
    std::cout << join_tables(tables, format);
    if (format != io::Format::json) {
        std::size_t runs = 0;
        for (const auto& e : study.fine) runs += e.measured.size();
        if (!o.runs.empty()) std::cout << "\nruns read from " << display_path(o.runs) << " (none run)";
        std::cout << "\n" << runs << " fine runs at " << study.fine.size() << (study.fine.size() == 1 ? " level" : " levels") << "; " << format_short(study.wall_s, 3)
                  << " s\n";
        if (study.second_look.any()) std::cout << study.second_look.describe() << "\n";
        if (study.wet) {
            std::cout << "transition model (decides; docs/exponent-estimate.md)" << (study.has_control() ? ", baseline-corrected (the dry control's offset, same seeds)" : "") << ":\n";
            for (std::size_t i = 0; i < study.fits.size(); ++i)
                std::cout << "  " << report::describe_fit(study.fits[i], &study.passing[i], plan.fine.tolerances.slump) << "\n";
            if (study.has_control()) {
                std::cout << "  raw, for comparison (the dry offset read as a shift in k):\n";
                for (const auto& f : study.raw_fits) std::cout << "    " << report::describe_fit(f, nullptr, 0) << "\n";
            }
            std::cout << "means shift with its seed bootstrap (for comparison; it undercovers where levels split):\n";
            for (const auto& e : study.estimates) std::cout << "  " << shift_summary(e) << "\n";
        }
        if (!study.wet) std::cout << "dry scene: no liquid to vary; the table is the dry control (coarse against fine)\n";
    }
    for (const auto& f : files.written) std::cerr << "wrote " << f.string() << "\n";
    return study.wet && !study.fits.back().determined ? 4 : 0;
}

}  // namespace

std::vector<Command> estimate_commands(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* c = app.add_subcommand("estimate-exponent",
                                 "measure k of gamma-bar = gamma S_f^k from the shift of slump response curves (exit 4: undetermined)");
    c->add_option("--scene", o->scene, "scene TOML (default: data/scenes/kantro_wet.toml); a dry scene gives the dry control");
    c->add_option("--sf", o->sfs, "scale factors S_f of the coarse curves")->capture_default_str();
    c->add_option("--levels", o->levels, "surface tension levels per curve, 3 to 12")->capture_default_str();
    c->add_option("--range", o->range, "lowest and highest surface tension factor of the fine curve, log-spaced")->capture_default_str();
    c->add_option("--offset", o->offset, "coarse levels at factor x gamma x S_f^offset")->capture_default_str();
    c->add_option("--seeds", o->seeds, "runs per level, 2 to 64")->capture_default_str();
    c->add_option("--resamples", o->resamples, "bootstrap resamples for the means shift's interval")->capture_default_str();
    c->add_option("--stands-below", o->stands_below, "a column whose slump over fill height is below this stood (transition model)")
        ->capture_default_str();
    c->add_option("--runs", o->runs,
                  "judge the runs in this CSV (docs/file-formats.md, runs file: e.g. another engine's, or estimate_runs.csv of an earlier study) "
                  "instead of running; --scene gives the surface tension and the tolerance");
    add_study_run_options(c, o->run, "the CSV files, estimate_runs.csv and the figure");
    return {{c, [o] { return run_estimate(*o); }}};
}

}  // namespace demscale::cli
