// demscale — command-line front end. Parses arguments, calls lib/, prints. No physics here.
// Exit codes: 0 success, 1 regression drift, 2 bad input, 3 runtime failure (I/O, gnuplot, solver),
// 5 runs handed to Slurm and not finished yet (run the same command again to collect them),
// 130 interrupted by SIGINT/SIGTERM (state checkpointed where the command supports resuming).
#include <iostream>
#include <stdexcept>

#include "cli_common.hpp"
#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "core/version.hpp"
#include "git_revision.hpp"
#include "slump/run_batch.hpp"

int main(int argc, char** argv) {
    using namespace demscale;
    CLI::App app{"demscale: similarity (scaling) laws for DEM of wet granular material (Yun & Park 2017)"};
    app.set_version_flag("--version", "demscale " + std::string(version) + " (git " + git_revision + ")");
    app.require_subcommand(1);
    auto commands = cli::similarity_commands(app);
    for (auto& c : cli::bridge_commands(app)) commands.push_back(std::move(c));
    for (auto& c : cli::bench_commands(app)) commands.push_back(std::move(c));
    for (auto& c : cli::slump_commands(app)) commands.push_back(std::move(c));
    for (auto& c : cli::pile_commands(app)) commands.push_back(std::move(c));
    for (auto& c : cli::study_commands(app)) commands.push_back(std::move(c));
    for (auto& c : cli::estimate_commands(app)) commands.push_back(std::move(c));
    for (auto& c : cli::report_commands(app)) commands.push_back(std::move(c));
    for (auto& c : cli::cluster_commands(app)) commands.push_back(std::move(c));

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "demscale: error: " << e.what() << "\n";
        return 2;
    }
    install_interrupt_handlers();
    try {
        for (auto& c : commands)
            if (*c.app) return c.run();
    } catch (const slump::RunsPending& e) {
        std::cerr << "demscale: " << e.what() << "\n";
        return 5;
    } catch (const Interrupted& e) {
        std::cerr << "demscale: " << e.what() << (e.checkpoint().empty() ? "" : "; checkpoint: " + e.checkpoint()) << "\n";
        return 130;
    } catch (const InputError& e) {
        std::cerr << "demscale: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "demscale: failed: " << e.what() << "\n";
        return 3;
    }
    return 0;
}
