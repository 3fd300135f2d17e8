// Running another program (Slurm's sbatch and squeue) and reading what it printed: argv is passed
// as it is, never through a shell, so scene names and paths need no quoting.
#pragma once

#include <string>
#include <vector>

namespace demscale {

struct CommandOutput {
    int exit_code = -1;   // the program's exit status; 127: it could not be started (not found)
    std::string output;   // stdout and stderr together, in the order written
};

// Runs argv[0] (looked up on PATH) with the rest as its arguments and waits for it.
CommandOutput run_command(const std::vector<std::string>& argv);

}  // namespace demscale
