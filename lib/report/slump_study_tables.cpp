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

std::vector<io::Cell> row(const slump::StudyRun& r, bool reference) {
    const auto& x = r.result;
    const auto& c = r.versus_reference;
    return {r.grain.sf,
            reference ? io::Cell(std::string("reference")) : io::Cell(r.grain.exponent),
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
            reference ? std::string("-") : verdict(r),
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
    t.rows.push_back(row(study.reference, true));
    for (const auto& r : study.runs) t.rows.push_back(row(r, false));
    t.notes.push_back("errors are signed (coarse - fine) / fine, except the profile's relative L2 norm");
    t.notes.push_back("speedup_work: fine particle-steps / coarse particle-steps; speedup_wall depends on the threads of each run");
    return t;
}

io::Table best_exponent_table(const slump::Study& study, const std::vector<double>& scale_factors) {
    io::Table t;
    t.title = "Exponent with the smallest profile error, per scale factor";
    t.columns = {"sf", "best_exponent", "profile_error_pct", "slump_error_pct", "spread_error_pct", "speedup_work", "verdict"};
    for (double sf : scale_factors) {
        const auto& b = study.best_at(sf);
        const auto& c = b.versus_reference;
        t.rows.push_back({sf, b.grain.exponent, 100 * c.profile_error, 100 * c.slump_error, 100 * c.spread_error, c.work_speedup,
                          verdict(b)});
    }
    return t;
}

}  // namespace demscale::report
