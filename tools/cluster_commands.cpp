// Subcommand cached-run: what one task of a Slurm job array runs (slump/slurm_backend.hpp). The
// submitting command wrote the scene beside the cache; this runs it and caches the result there.
#include "cli_common.hpp"
#include "core/input_error.hpp"

namespace demscale::cli {

std::vector<Command> cluster_commands(CLI::App& app) {
    struct Options {
        std::string cache = default_cache, key;
        int threads = 1;
        bool force_dt = false;
    };
    auto o = std::make_shared<Options>();
    auto* c = app.add_subcommand("cached-run", "one slump run of a batch handed to Slurm, into its cache (what each array task runs)");
    c->add_option("--cache", o->cache, "the cache folder the batch was submitted with")->capture_default_str();
    c->add_option("--key", o->key, "the run's key: the scene is <cache>/slurm/<key>.scene")->required();
    c->add_option("--threads", o->threads, "OpenMP threads")->capture_default_str();
    c->add_flag("--force-dt", o->force_dt, "accept a time step above 0.2 x the Rayleigh time");
    return {{c, [o] {
                 if (o->threads < 1) throw InputError("--threads", std::to_string(o->threads), ">= 1");
                 slump::run_slurm_task(o->cache, o->key, o->threads, o->force_dt, progress_output("cached-run").log);
                 return 0;
             }}};
}

}  // namespace demscale::cli
