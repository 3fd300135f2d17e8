// A runs file: one row per slump run, the measures the exponent's estimator reads (docs/file-formats.md,
// "Runs file"). Every study writes its runs as one (runs.csv in --out), and `estimate-exponent --runs`
// reads one back, or one made by any engine, and gives the same answer as on the runs themselves.
// Columns: sf (S_f, 1 fine), gamma_n_per_m (the run's own surface tension, N/m; 0: the dry control)
// or gamma_factor (of the scene's γ), seed (an integer naming the pile; a seed's runs at every level
// are resampled together), slump_over_height, spread_over_d0 (spread over the cone's bottom
// diameter), optionally came_to_rest (yes/no) and unusable (why its fill could not be used; the
// measures then n/a). Numbers are written in their shortest exact form, so a file read back holds
// the same doubles.
#pragma once

#include <string>
#include <vector>

#include "io/table_format.hpp"
#include "slump/run_batch.hpp"

namespace demscale::slump {

struct RunRow {
    double sf = 1;
    double gamma = 0;  // N/m; 0: no liquid (the dry control, or a dry scene)
    long seed = 0;
    double slump_over_height = 0, spread_over_d0 = 0;
    bool at_rest = true;
    std::string unusable;  // non-empty: no measures
};

// A run's row: its S_f, its own surface tension (0 without liquid), seed and measures; bottom_diameter
// of the cone, m (the spread's scale).
RunRow run_row(const StudyRun& run, double bottom_diameter);

io::Table runs_table(const std::vector<RunRow>& rows, const std::string& scene_label);

// Throws InputError naming the file, line and column (and the accepted range) of the first bad
// field: a missing column, a number that is not one or is out of range (S_f ≥ 1, γ ≥ 0, seed an
// integer ≥ 0, measures finite), a run listed twice (same S_f, γ and seed), or no run at all.
// scene_gamma (N/m) turns a gamma_factor column into γ.
std::vector<RunRow> read_runs_file(const std::string& path, double scene_gamma);
std::vector<RunRow> parse_runs(const std::string& text, const std::string& source, double scene_gamma);

// Adds one run to a runs file, creating it when absent, and writes it whole through a temporary
// file. Throws InputError naming the file (and nothing is written) when it is not a runs file as
// demscale writes them (its header row differs), is malformed, or already holds this run (same
// S_f, surface tension and seed). field: the option that named the file.
void append_run(const std::string& field, const std::string& path, const RunRow& row, const std::string& scene_label);

}  // namespace demscale::slump
