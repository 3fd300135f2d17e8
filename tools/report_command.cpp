// Subcommand report: the similarity report (HTML and Markdown) for a scene.
#include <cstdio>
#include <iostream>

#include "cli_common.hpp"
#include "git_revision.hpp"
#include "core/input_error.hpp"
#include "report/similarity_report.hpp"

namespace demscale::cli {

namespace {

struct Options {
    std::string scene, config, exponents, sfs;
    std::string out_dir = "report";
    std::string cache = default_cache;
    bool quick = false, no_cache = false;
    int jobs = 0, threads = 0, seeds = 0;  // seeds 0: 8, or 3 with --quick
    bool estimate = false;                 // the measured-exponent section
    std::string estimate_sf, estimate_range = "0.5,1.6";
    int estimate_levels = 0;               // 0: 5, or 3 with --quick
    int estimate_seeds = 0;                // 0: 4, or the report's --seeds with --quick
    std::string baseline = "dry";
    long seed_base = 0;
    SlurmOptions slurm;
    EngineOptions engine;
};

int run_report(const Options& o) {
    report::ReportOptions r;
    r.scene_path = !o.scene.empty() ? o.scene : o.quick ? shipped("scenes/small_wet.toml") : default_scene;
    r.scene_label = display_path(r.scene_path);
    auto scene = load_scene(r.scene_path);  // its bridge warnings, before the long run
    apply_engine(scene, o.engine);           // a scene LIGGGHTS cannot express is refused here
    r.liggghts_ranks = scene.liggghts_ranks;
    // The similarity table follows the scene the user names; the shipped scenes go with the paper's Table 1.
    r.similarity = similarity_inputs(o.config, o.scene);
    r.bridge_table_path = default_bridge_table;
    if (!o.exponents.empty()) r.exponents = parse_exponents(o.exponents, "--exponents");
    r.scale_factors = scale_factors_or_usable(o.sfs.empty() && o.quick ? "1.4" : o.sfs, scene);
    r.quick = o.quick;
    r.out_dir = o.out_dir;
    if (!o.no_cache) r.cache_dir = o.cache;
    const auto par = parallelism(o.jobs, o.threads, o.engine);
    r.jobs = par.jobs, r.threads_per_job = par.threads_per_job;
    r.slurm = slurm_settings(o.slurm);
    if (o.seeds < 0) throw InputError("--seeds", std::to_string(o.seeds), "1 to 64");
    r.seeds = o.seeds > 0 ? o.seeds : o.quick ? 3 : 8;
    r.baseline = parse_baseline(o.baseline);
    slump::SlumpScene seeded;
    apply_seed_base(seeded, o.seed_base);  // validates it
    r.seed_base = o.seed_base > 0 ? seeded.seed : 0;
    r.git_revision = demscale::git_revision;  // the build's, refreshed at every build
    if (o.estimate) {
        slump::ResponsePlan e;
        e.scale_factors = parse_number_list(!o.estimate_sf.empty() ? o.estimate_sf : o.quick ? "1.4" : "1.4,1.96", "--estimate-sf", 0, 100);
        e.factors = parse_factor_range(o.estimate_range, o.estimate_levels > 0 ? o.estimate_levels : o.quick ? 3 : 5,
                                       "--estimate-range", "--estimate-levels");
        if (o.estimate_seeds < 0) throw InputError("--estimate-seeds", std::to_string(o.estimate_seeds), "2 to 64");
        e.seeds = o.estimate_seeds > 0 ? o.estimate_seeds : o.quick ? r.seeds : 4;
        e.baseline = r.baseline;
        r.estimate = e;
    }
    const auto progress = progress_output("report");
    r.live = progress.live;
    const auto out = report::write_similarity_report(r, progress.log);
    std::cout << "wrote " << out.html.string() << "\nwrote " << out.markdown.string() << " (figures in "
              << (std::filesystem::path(o.out_dir) / "figures").string() << ")\n"
              << out.caveats.size() << " caveat(s); " << format_short(out.wall_s, 3) << " s\n";
    return 0;
}

}  // namespace

std::vector<Command> report_commands(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* c = app.add_subcommand("report", "the similarity report: inputs, Table 1, Figs. 3-4, bridge accuracy, slump study, caveats");
    c->add_option("--scene", o->scene, "slump scene (default: data/scenes/kantro_wet.toml; --quick: small_wet.toml)");
    c->add_option("--config", o->config, "Table 1 style inputs for the similarity table (default: the --scene's own; without --scene data/table1.toml)");
    c->add_option("--exponent,--exponents", o->exponents, "candidate exponents k, comma-separated (default: the scene's or config's, 1,3)");
    c->add_option("--sf", o->sfs, "scale factors of the coarse runs (default: those of 1.4,1.96,2.74,3.84 the scene's cone does not limit; --quick: 1.4)");
    c->add_option("--out", o->out_dir, "folder for report.html, report.md and figures/ (default: report/)");
    c->add_flag("--quick", o->quick, "small scene, coarse grids: the whole report in under a minute");
    c->add_option("--cache", o->cache, "folder of finished slump runs, reused by scene key (default: cache/)");
    c->add_flag("--no-cache", o->no_cache, "run every slump; read and write no cache");
    c->add_option("--seeds", o->seeds, "runs per ensemble, fine and each (S_f, k) (default 8; --quick: 3)");
    c->add_option("--jobs", o->jobs, "slump runs side by side (default: one per core)");
    c->add_option("--seed-base", o->seed_base, "first seed of every ensemble (default: the scene's `seed`); another base draws new piles");
    c->add_option("--baseline", o->baseline, "dry: the dry control of the same seeds decides the verdicts and k-hat; none: raw")
        ->capture_default_str();
    c->add_option("--threads", o->threads, "OpenMP threads per run (default: cores / jobs)");
    add_backend_options(c, o->slurm);
    add_engine_options(c, o->engine);
    c->add_flag("--estimate", o->estimate, "add the measured exponent: response curves and k-hat (costs the most; see estimate-exponent)");
    c->add_option("--estimate-sf", o->estimate_sf, "scale factors of the measured exponent (default 1.4,1.96; --quick: 1.4)");
    c->add_option("--estimate-range", o->estimate_range, "lowest and highest surface tension factor of its fine curve")->capture_default_str();
    c->add_option("--estimate-levels", o->estimate_levels, "surface tension levels per curve, 3 to 12 (default 5; --quick: 3)");
    c->add_option("--estimate-seeds", o->estimate_seeds, "runs per level of the measured exponent (default 4; --quick: --seeds)");
    return {{c, [o] { return run_report(*o); }}};
}

}  // namespace demscale::cli
