#include "slump/runs_file.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <tuple>

#include "core/input_error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_reader.hpp"
#include "io/input_file.hpp"
#include "slump/ensemble_verdict.hpp"

namespace demscale::slump {

RunRow run_row(const StudyRun& run, double bottom_diameter) {
    RunRow m;
    m.sf = run.grain.sf, m.gamma = run.scene.wet ? run.scene.liquid.surface_tension_n_per_m : 0.0;
    m.seed = static_cast<long>(run.scene.seed), m.unusable = run.unusable;
    if (m.unusable.empty()) {
        m.slump_over_height = slump_over_height(run.result), m.spread_over_d0 = run.result.final.spread / bottom_diameter;
        m.at_rest = run.result.came_to_rest;
    }
    return m;
}

io::Table runs_table(const std::vector<RunRow>& rows, const std::string& scene_label) {
    io::Table t;
    t.title = "Slump runs, one row per run (" + scene_label + ")";
    t.metadata = {{"scene", scene_label}};
    t.columns = {"sf", "gamma_n_per_m", "seed", "slump_over_height", "spread_over_d0", "came_to_rest", "unusable"};
    for (const auto& r : rows) {
        const bool measured = r.unusable.empty();
        t.rows.push_back({r.sf, r.gamma, static_cast<double>(r.seed), measured ? io::Cell(r.slump_over_height) : io::Cell(io::not_available),
                          measured ? io::Cell(r.spread_over_d0) : io::Cell(io::not_available), r.at_rest ? "yes" : "no", r.unusable});
    }
    t.notes.push_back("gamma_n_per_m: the run's own surface tension (coarse runs: gamma-bar); 0: no liquid (the dry control)");
    t.notes.push_back("slump_over_height: slump over fill height; spread_over_d0: the spread over the cone's bottom diameter "
                      "(docs/slump-measures.md); read back by estimate-exponent --runs (docs/file-formats.md)");
    return t;
}

std::vector<RunRow> parse_runs(const std::string& text, const std::string& source, double scene_gamma) {
    const io::CsvData csv = io::parse_csv(text, source);
    auto column = [&](const std::string& name) -> int {
        for (std::size_t i = 0; i < csv.header.size(); ++i)
            if (csv.header[i] == name) return static_cast<int>(i);
        return -1;
    };
    const int sf = column("sf"), gamma = column("gamma_n_per_m"), factor = column("gamma_factor"), seed = column("seed"),
              slump = column("slump_over_height"), spread = column("spread_over_d0"), rest = column("came_to_rest"),
              unusable = column("unusable");
    for (const auto& [index, name] : {std::pair{sf, "sf"}, {seed, "seed"}, {slump, "slump_over_height"}, {spread, "spread_over_d0"}})
        if (index < 0) throw InputError(source + " (header row)", "no column " + std::string(name),
                                        "the columns sf, gamma_n_per_m (or gamma_factor), seed, slump_over_height, spread_over_d0");
    if ((gamma < 0) == (factor < 0))
        throw InputError(source + " (header row)", gamma < 0 ? "neither gamma_n_per_m nor gamma_factor" : "both gamma_n_per_m and gamma_factor",
                         "one of the columns gamma_n_per_m (N/m) and gamma_factor (of the scene's surface tension)");
    std::vector<RunRow> rows;
    std::set<std::tuple<double, double, long>> seen;
    for (std::size_t r = 0; r < csv.rows.size(); ++r) {
        const auto& fields = csv.rows[r];
        const std::string line = source + ":" + std::to_string(csv.row_lines[r]);
        auto where = [&](int col) { return line + ":" + std::to_string(col + 1) + " (" + csv.header[static_cast<std::size_t>(col)] + ")"; };
        auto number = [&](int col, double lo, const std::string& accepted) {
            const std::string& f = fields[static_cast<std::size_t>(col)];
            const auto x = io::finite_number(f);
            if (!x || *x < lo) throw InputError(where(col), f.empty() ? "(empty)" : f, accepted);
            return *x;
        };
        RunRow row;
        row.sf = number(sf, 1, "a scale factor S_f >= 1 (1: the fine scene)");
        row.gamma = gamma >= 0 ? number(gamma, 0, "a surface tension >= 0 in N/m (0: the dry control)")
                               : scene_gamma * number(factor, 0, "a factor >= 0 of the scene's surface tension (0: the dry control)");
        const double s = number(seed, 0, "an integer seed >= 0");
        if (s != std::floor(s) || s > 9.0e15) throw InputError(where(seed), fields[static_cast<std::size_t>(seed)], "an integer seed >= 0");
        row.seed = static_cast<long>(s);
        if (unusable >= 0) row.unusable = fields[static_cast<std::size_t>(unusable)];
        if (row.unusable.empty()) {
            row.slump_over_height = number(slump, -1, "a finite slump over fill height, > -1");
            row.spread_over_d0 = number(spread, 0, "a finite spread over the bottom diameter, >= 0");
        }
        if (rest >= 0) {
            const std::string& f = fields[static_cast<std::size_t>(rest)];
            if (f != "yes" && f != "no" && !f.empty()) throw InputError(where(rest), f, "yes or no (empty: yes)");
            row.at_rest = f != "no";
        }
        if (!seen.insert({row.sf, row.gamma, row.seed}).second)
            throw InputError(line, "S_f " + format_number(row.sf) + ", gamma " + format_number(row.gamma) + ", seed " + std::to_string(row.seed),
                             "each run once (this S_f, surface tension and seed came before)");
        rows.push_back(std::move(row));
    }
    if (rows.empty()) throw InputError(source, "(no runs)", "at least one row of runs");
    return rows;
}

void append_run(const std::string& field, const std::string& path, const RunRow& row, const std::string& scene_label) {
    std::vector<RunRow> rows;
    if (std::filesystem::exists(path)) {
        const std::string text = io::read_input_file(field, path, "a runs file (CSV)");
        const auto ours = runs_table({}, scene_label).columns;
        if (io::parse_csv(text, path).header != ours) {
            std::string names;
            for (const auto& c : ours) names += (names.empty() ? "" : ",") + c;
            throw InputError(path + " (header row)", "other columns", "a runs file as demscale writes them (" + names + "), or a new file");
        }
        rows = parse_runs(text, path, 0);
        for (const auto& r : rows)
            if (r.sf == row.sf && r.gamma == row.gamma && r.seed == row.seed)
                throw InputError(field + " " + path, "S_f " + format_number(row.sf) + ", gamma " + format_number(row.gamma) + ", seed " +
                                                         std::to_string(row.seed),
                                 "a run the file does not hold yet (it has this S_f, surface tension and seed)");
    }
    rows.push_back(row);
    io::write_file_atomically(path, io::render(runs_table(rows, scene_label), io::Format::csv));
}

std::vector<RunRow> read_runs_file(const std::string& path, double scene_gamma) {
    return parse_runs(io::read_input_file("--runs", path, "a runs file (CSV)"), path, scene_gamma);
}

}  // namespace demscale::slump
