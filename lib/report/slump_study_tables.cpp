#include "report/slump_study_tables.hpp"

#include <cmath>

#include "core/input_error.hpp"

namespace demscale::report {

namespace {

std::string verdict(const slump::StudyRun& r) { return r.within_tolerance ? "pass" : "FAIL"; }

std::string remarks(const slump::StudyRun& r) {
    std::string t;
    if (!r.result.came_to_rest) t += "not at rest; ";
    for (const auto& w : r.warnings) t += w + "; ";
    if (!t.empty()) t.resize(t.size() - 2);
    return t;
}

// label: what stands in the exponent column for fine runs ("reference", "seed 2"); empty for coarse runs.
std::vector<io::Cell> row(const slump::StudyRun& r, const std::string& label) {
    const bool reference = label == "reference";
    const auto& x = r.result;
    const auto& c = r.versus_reference;
    return {r.grain.sf,
            label.empty() ? io::Cell(r.grain.exponent) : io::Cell(label),
            static_cast<double>(x.particles),
            static_cast<double>(x.steps),
            x.dt * 1e6,
            x.wall_s,
            reference ? 1.0 : c.wall_speedup,
            reference ? 1.0 : c.work_speedup,
            x.slump() * 1e3,
            100 * c.slump_error,
            x.final.spread_d95 * 1e3,
            100 * c.spread_error,
            100 * c.profile_error,
            x.final.repose_angle_deg,
            label.empty() ? verdict(r) : std::string("-"),
            remarks(r)};
}

}  // namespace

io::Table study_table(const slump::Study& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Slump test, coarse runs against the fine reference (" + scene_label + ")";
    t.metadata = {{"scene", scene_label},
                  {"tolerances", "slump " + format_short(100 * study.tolerances.slump) + " %, spread d95 " +
                                     format_short(100 * study.tolerances.spread) + " %, profile L2 " +
                                     format_short(100 * study.tolerances.profile) + " %"}};
    t.columns = {"sf",          "exponent",       "particles",     "steps",           "dt_us",
                 "wall_s",      "speedup_wall",   "speedup_work",  "slump_mm",        "slump_error_pct",
                 "spread_d95_mm", "spread_error_pct", "profile_error_pct", "repose_deg", "verdict", "remarks"};
    t.rows.push_back(row(study.reference, "reference"));
    for (const auto& r : study.replicas) t.rows.push_back(row(r, "seed " + std::to_string(r.scene.seed)));
    for (const auto& r : study.runs) t.rows.push_back(row(r, ""));
    t.notes.push_back("errors are signed (coarse - fine) / fine, except the profile's relative L2 norm");
    if (!study.replicas.empty())
        t.notes.push_back("rows 'seed N': the fine scene filled with another seed, against the reference: the noise floor of every error");
    t.notes.push_back("speedup_work: fine particle-steps / coarse particle-steps; speedup_wall depends on the threads of each run");
    return t;
}

io::Table best_exponent_table(const slump::Study& study, const std::vector<double>& scale_factors) {
    io::Table t;
    t.title = "Exponent with the smallest profile error, per scale factor";
    t.columns = {"sf", "best_exponent", "profile_error_pct", "slump_error_pct", "spread_error_pct", "speedup_work", "verdict"};
    if (!study.replicas.empty()) {
        const auto n = study.noise_floor();
        t.metadata = {{"noise floor (fine vs fine, other seeds, largest)",
                       "profile " + format_short(100 * n.profile_error, 3) + " %, slump " + format_short(100 * n.slump_error, 3) +
                           " %, spread " + format_short(100 * n.spread_error, 3) + " %"}};
    }
    for (double sf : scale_factors) {
        const auto& b = study.best_at(sf);
        const auto& c = b.versus_reference;
        t.rows.push_back({sf, b.grain.exponent, 100 * c.profile_error, 100 * c.slump_error, 100 * c.spread_error, c.work_speedup,
                          verdict(b)});
    }
    return t;
}

}  // namespace demscale::report
