#include "report/slump_study_tables.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/input_error.hpp"
#include "stats/summary.hpp"

namespace demscale::report {

namespace {

std::string remarks(const slump::StudyRun& r) {
    if (!r.unusable.empty()) return "UNUSABLE: " + r.unusable;
    std::string t;
    if (!r.result.came_to_rest) t += "not at rest; ";
    for (const auto& w : r.warnings) t += w + "; ";
    if (!t.empty()) t.resize(t.size() - 2);
    return t;
}

std::string tolerances_text(const slump::Tolerances& t) {
    return "slump " + format_short(100 * t.slump) + " % of the fill height, spread " + format_short(100 * t.spread) +
           " %, profile " + format_short(100 * t.profile) + " %";
}

// "+1.2 [−0.4, +2.8]" in %.
std::string interval_pct(double estimate, const stats::Interval& i) {
    auto s = [](double x) { return (x >= 0 ? "+" : "") + format_short(100 * x, 3); };
    return s(estimate) + " [" + s(i.low) + ", " + s(i.high) + "]";
}

io::Cell mean_or_na(const std::vector<double>& v) {
    if (v.empty()) return io::Cell(io::not_available);
    return stats::summarize(v).mean;
}

}  // namespace

namespace {

// One row of the verdict table: an ensemble's three criteria under one comparison.
std::vector<io::Cell> verdict_row(const slump::EnsembleVerdict& v, const std::string& comparison, bool decides) {
    if (!v.unusable.empty())
        return {v.sf, v.exponent, comparison, 0.0, io::Cell(io::not_available), io::Cell(io::not_available),
                io::Cell(io::not_available), "UNUSABLE FILL", io::Cell(io::not_available), v.unusable + " (not judged)"};
    std::string smallest, notes;
    std::vector<io::Cell> row = {v.sf, v.exponent, comparison, static_cast<double>(v.coarse_seeds)};
    for (const char* measure : {"slump", "spread", "profile"}) {
        const auto c = std::find_if(v.criteria.begin(), v.criteria.end(), [&](const auto& x) { return x.measure == measure; });
        if (c == v.criteria.end()) {  // a runs file's verdict: no profiles
            row.push_back("not judged");
            continue;
        }
        row.push_back(interval_pct(c->estimate, c->interval) + " " + stats::verdict_name(c->verdict));
        smallest += (smallest.empty() ? "" : " / ") + format_short(100 * c->smallest_tolerance, 3);
        if (!c->reason.empty()) notes += c->measure + ": " + c->reason + "; ";
    }
    for (const auto& w : v.warnings) notes += w + "; ";
    if (!notes.empty()) notes.resize(notes.size() - 2);
    row.push_back(stats::verdict_name(v.overall) + (decides ? " (decides)" : ""));
    row.push_back(smallest);
    row.push_back(notes);
    return row;
}

// The verdict table's rows and common notes: raw, and with a control the baseline-corrected verdict
// (which decides) and the dry control, the latter once per dry scene (show_control).
struct VerdictRows {
    const std::vector<slump::EnsembleVerdict>& raw;
    const std::vector<slump::EnsembleVerdict>& corrected;  // empty: no control
    const std::vector<slump::EnsembleVerdict>& controls;
    std::vector<bool> show_control;                          // per entry of raw
    slump::Tolerances tolerances;
    stats::Verdict overall;
};

io::Table verdict_table_of(const VerdictRows& v, const std::string& scene_label, const std::string& profile_note) {
    const bool control = !v.corrected.empty();
    io::Table t;
    t.title = "Verdict per scale factor and exponent: coarse ensemble against the fine ensemble (" + scene_label + ")";
    t.metadata = {{"scene", scene_label}, {"tolerances", tolerances_text(v.tolerances)}};
    // One verdict over all rows means something for one candidate k (check-exponent), not across several.
    const bool one_exponent = std::all_of(v.raw.begin(), v.raw.end(), [&](const auto& e) { return e.exponent == v.raw.front().exponent; });
    if (one_exponent) t.metadata.push_back({"overall", stats::verdict_name(v.overall)});
    t.metadata.push_back({"decides", control ? "the baseline-corrected comparison (dry control of the same seeds removed)"
                                             : "the raw comparison (--baseline none, or a dry scene: no baseline runs)"});
    t.columns = {"sf", "exponent", "comparison", "seeds", "slump_diff_pct_of_height", "spread_diff_pct", "profile_distance_pct", "verdict",
                 "smallest_tolerances_pct", "notes"};
    t.headings = {"S_f", "k", "comparison", "seeds", "slump difference, % of fill height [95 % interval]",
                  "spread difference, % [95 % interval]", "profile distance, % [95 % interval]", "verdict",
                  "smallest tolerances these data confirm, % (slump / spread / profile)", "notes"};
    for (std::size_t i = 0; i < v.raw.size(); ++i) {
        t.rows.push_back(verdict_row(v.raw[i], "raw", !control));
        if (!control || !v.raw[i].unusable.empty()) continue;
        t.rows.push_back(verdict_row(v.corrected[i], "baseline-corrected", true));
        if (v.show_control[i]) {
            auto row = verdict_row(v.controls[i], "dry control", false);
            row[1] = io::Cell(io::not_available);
            t.rows.push_back(std::move(row));
        }
    }
    t.notes.push_back("each cell: estimate [95 % interval], in %; slump as (coarse - fine) mean slump over the fill height, Welch t; "
                      "spread (diameter at half height) as the difference of means over the fine mean, Welch t; " + profile_note);
    if (control)
        t.notes.push_back("raw: the wet ensembles as they are; baseline-corrected: each seed's wet value less its dry twin's, coarse "
                          "against fine (profile: the wet-minus-dry mean shapes), which removes the offset the same S_f shows without "
                          "liquid; dry control: the dry coarse ensemble against the dry fine one, that offset itself (docs/verdicts.md)");
    if (std::any_of(v.raw.begin(), v.raw.end(), [](const auto& e) { return !e.unusable.empty(); }))
        t.notes.push_back("UNUSABLE FILL: the cone could not hold the scene's mass of these spheres (the pour jammed in the top opening, "
                          "or the fill did not fit under the cone's top): not a column, not judged, not in the overall verdict");
    t.notes.push_back("PASS: the interval lies inside the tolerance; FAIL: wholly outside it; INCONCLUSIVE: neither (more seeds narrow it)");
    return t;
}

}  // namespace

io::Table verdict_table(const slump::Study& study, const std::string& scene_label) {
    // The dry control once per S_f when the dry scenes of several k are one (nothing else scaled).
    std::vector<bool> show(study.verdicts.size(), false);
    std::set<std::string> dry_shown;  // run keys (run_batch sets them)
    if (study.has_control())
        for (std::size_t i = 0; i < study.verdicts.size(); ++i)
            show[i] = study.verdicts[i].unusable.empty() && dry_shown.insert(study.dry_coarse[i].front().key).second;
    auto t = verdict_table_of({study.verdicts, study.corrected, study.controls, show, study.tolerances, study.overall()}, scene_label,
                              "profile as the distance between the mean shapes, bootstrap over seeds");
    for (const auto& l : study.limited) {
        std::string why;
        for (const auto& r : l.reasons) why += (why.empty() ? "" : "; ") + r;
        t.rows.push_back({l.sf, io::Cell(io::not_available), "none", 0.0, io::Cell(io::not_available), io::Cell(io::not_available),
                          io::Cell(io::not_available), "GEOMETRY-LIMITED", io::Cell(io::not_available), why + " (not run)"});
    }
    if (!study.limited.empty())
        t.notes.push_back("GEOMETRY-LIMITED: the coarse scene is below the scene's [check] limits (top opening, fill height in particle "
                          "diameters, spheres per fill), so the cone rather than the exponent decides its runs; it is neither PASS nor "
                          "FAIL and does not enter the overall verdict");
    if (study.second_look.any()) t.notes.push_back(study.second_look.describe());
    return t;
}

io::Table verdict_table(const slump::RunsVerdicts& verdicts, const std::string& scene_label, const std::string& source) {
    auto t = verdict_table_of({verdicts.raw, verdicts.corrected, verdicts.controls, std::vector<bool>(verdicts.raw.size(), true),
                               verdicts.tolerances, verdicts.overall()},
                              scene_label, "profile not judged: a runs file holds no profiles, so the verdict rests on slump and spread");
    t.metadata.push_back({"runs", source});
    return t;
}

io::Table ensemble_table(const slump::Study& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Ensembles: means over the seeds (" + scene_label + ")";
    t.columns = {"sf", "exponent", "seeds", "particles", "steps", "wall_s", "speedup_work", "speedup_wall", "slump_over_height",
                 "slump_over_height_sd", "slump_mm", "slump_fine_radii", "spread_mm", "spread_sd_mm", "profile_distance_pct",
                 "at_rest", "time_to_rest_s", "fill_mass_g", "fill_mass_ratio", "fill_height_mm", "fill_solid_fraction", "fill_coordination",
                 "repose_deg"};
    double fine_mass = 0;
    for (const auto* r : study.fine_ensemble()) fine_mass += r->fill.mass / static_cast<double>(study.fine_ensemble().size());
    const double r_fine = study.reference.scene.radius_m;
    // dry: the dry control's rows, whose shape the wet fine mean does not measure (n/a).
    auto row = [&](const std::vector<const slump::SlumpResult*>& runs, double sf, io::Cell exponent, bool dry = false) {
        std::vector<double> sh, mm, d95, prof, rest_t, phi, z, repose, particles, steps, wall, work, mass, height;
        std::size_t at_rest = 0;
        for (const auto* r : runs) {
            sh.push_back(r->slump() / r->initial_height), mm.push_back(r->slump() * 1e3), d95.push_back(r->final.spread * 1e3);
            prof.push_back(100 * slump::compare_to(study.fine, *r).profile_error);
            if (r->came_to_rest) ++at_rest, rest_t.push_back(r->time_to_rest());
            phi.push_back(r->fill.solid_fraction), z.push_back(r->fill.coordination);
            mass.push_back(r->fill.mass * 1e3), height.push_back(r->fill.height * 1e3);
            if (r->final.repose_angle_deg) repose.push_back(*r->final.repose_angle_deg);
            particles.push_back(double(r->particles)), steps.push_back(double(r->steps + r->pour_steps)), wall.push_back(r->wall_s);
            work.push_back(r->particle_steps());
        }
        const auto s = stats::summarize(sh), d = stats::summarize(d95);
        t.rows.push_back({sf, exponent, static_cast<double>(runs.size()), stats::summarize(particles).mean, stats::summarize(steps).mean,
                          stats::summarize(wall).mean, study.fine.particle_steps / stats::summarize(work).mean, study.fine.wall_s / stats::summarize(wall).mean,
                          s.mean, s.sd, stats::summarize(mm).mean, stats::summarize(mm).mean * 1e-3 / r_fine, d.mean, d.sd,
                          dry ? io::Cell(io::not_available) : io::Cell(stats::summarize(prof).mean), std::to_string(at_rest) + " of " + std::to_string(runs.size()),
                          mean_or_na(rest_t), stats::summarize(mass).mean, stats::summarize(mass).mean * 1e-3 / fine_mass,
                          stats::summarize(height).mean, stats::summarize(phi).mean, stats::summarize(z).mean, mean_or_na(repose)});
    };
    row(study.fine_ensemble(), 1.0, io::Cell(io::not_available));
    for (std::size_t i = 0; i < study.runs.size(); ++i)
        if (study.verdicts[i].unusable.empty()) row(study.coarse_ensemble(i), study.runs[i].grain.sf, study.runs[i].grain.exponent);
    if (study.has_control()) {
        row(study.dry_fine_ensemble(), 1.0, "dry", true);
        std::set<std::string> seen;
        for (std::size_t i = 0; i < study.dry_coarse.size(); ++i)
            if (study.verdicts[i].unusable.empty() && seen.insert(study.dry_coarse[i].front().key).second) row(study.dry_coarse_ensemble(i), study.runs[i].grain.sf, "dry", true);
        t.notes.push_back("exponent 'dry': the dry control, the same scene and seeds without liquid (docs/verdicts.md)");
    }
    t.notes.push_back("the first row is the fine ensemble (S_f = 1, no exponent)");
    t.notes.push_back("profile_distance_pct: mean over the seeds of each run's shape distance from the fine mean shape; for the fine "
                      "ensemble, its own run-to-run scatter (the noise floor)");
    t.notes.push_back("steps, wall_s and the speed-ups count the pour too");
    t.notes.push_back("time_to_rest_s: from the cone's removal until the pile was at rest (mean over the runs that came to rest)");
    t.notes.push_back("fill_mass_ratio: the ensemble's mean fill mass over the fine ensemble's; fill_height_mm: the fill's surface "
                      "height before the lift (a looser coarse packing of the same mass stands higher)");
    t.notes.push_back("fill_solid_fraction: sphere volume over the cone volume below the fill's surface, before the lift");
    return t;
}

io::Table study_table(const slump::Study& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Slump runs, each against the fine ensemble's means (" + scene_label + ")";
    t.metadata = {{"scene", scene_label}, {"tolerances", tolerances_text(study.tolerances)}};
    t.columns = {"sf",       "exponent",        "seed",          "particles",      "steps",          "dt_us",
                 "wall_s",   "speedup_wall",    "speedup_work",  "slump_mm",       "slump_over_height", "slump_error_pct_of_height",
                 "spread_mm", "spread_error_pct", "profile_error_pct", "repose_deg", "time_to_rest_s", "remarks"};
    auto add = [&](const slump::StudyRun& r, io::Cell exponent) {
        const auto& x = r.result;
        const auto& c = r.versus_reference;
        if (!r.unusable.empty()) {  // no column, no measures
            std::vector<io::Cell> row(t.columns.size(), io::Cell(io::not_available));
            row[0] = r.grain.sf, row[1] = exponent, row[2] = static_cast<double>(r.scene.seed), row.back() = remarks(r);
            t.rows.push_back(std::move(row));
            return;
        }
        t.rows.push_back({r.grain.sf, exponent, static_cast<double>(r.scene.seed), static_cast<double>(x.particles),
                          static_cast<double>(x.steps + x.pour_steps), x.dt * 1e6, x.wall_s, c.wall_speedup, c.work_speedup, x.slump() * 1e3,
                          x.slump() / x.initial_height, 100 * c.slump_error, x.final.spread * 1e3, 100 * c.spread_error,
                          100 * c.profile_error, x.final.repose_angle_deg ? io::Cell(*x.final.repose_angle_deg) : io::Cell(io::not_available),
                          x.came_to_rest ? io::Cell(x.time_to_rest()) : io::Cell(io::not_available), remarks(r)});
    };
    add(study.reference, io::Cell(io::not_available));
    for (const auto& r : study.replicas) add(r, io::Cell(io::not_available));
    for (std::size_t i = 0; i < study.runs.size(); ++i)
        for (const auto* r : study.coarse_runs(i)) add(*r, study.runs[i].grain.exponent);
    // The dry control's runs, each distinct scene once; remarks say what they are.
    std::set<std::string> seen;
    auto add_dry = [&](const slump::StudyRun& r) {
        if (!seen.insert(r.key).second) return;
        add(r, io::Cell(io::not_available));
        auto& remark = std::get<std::string>(t.rows.back().back());
        remark = "dry control" + (remark.empty() ? "" : "; " + remark);
    };
    for (const auto& r : study.dry_fine) add_dry(r);
    for (const auto& e : study.dry_coarse)
        for (const auto& r : e) add_dry(r);
    t.notes.push_back("rows with S_f = 1 and no exponent: the fine ensemble");
    t.notes.push_back("slump_error_pct_of_height: slump over the fill height minus the fine ensemble's mean, in % of the height");
    t.notes.push_back("spread and profile errors: relative to the fine ensemble's mean spread and mean shape (fringe and empty bins do "
                      "not count; docs/slump-measures.md)");
    return t;
}

io::Table best_exponent_table(const slump::Study& study, const std::vector<double>& scale_factors) {
    io::Table t;
    t.title = "Exponent whose ensemble has the smallest profile distance, per scale factor";
    t.columns = {"sf", "best_exponent", "profile_distance_pct", "profile_low_pct", "profile_high_pct", "not_told_apart",
                 "slump_diff_pct_of_height", "spread_diff_pct", "verdict"};
    const auto& n = study.noise;
    t.metadata = {{"noise floor (fine ensemble, sd over seeds)",
                   "slump " + format_short(100 * n.slump_over_height.sd, 3) + " % of the height, spread " +
                       format_short(100 * n.spread.sd / std::max(n.spread.mean, 1e-300), 3) + " %, profile " +
                       format_short(100 * n.profile.mean, 3) + " % (each fine run from the fine mean shape)"}};
    if (study.has_control()) t.metadata.push_back({"judged", "baseline-corrected (dry control removed)"});
    for (double sf : scale_factors) {
        const auto& b = study.best_at(sf);
        std::string others;
        for (double k : study.not_told_apart_from_best(sf)) others += (others.empty() ? "k = " : ", ") + format_short(k);
        t.rows.push_back({sf, b.exponent, 100 * b.criteria[2].estimate, 100 * b.criteria[2].interval.low, 100 * b.criteria[2].interval.high,
                          others.empty() ? "none" : others, 100 * b.criteria[0].estimate, 100 * b.criteria[1].estimate,
                          stats::verdict_name(b.overall)});
    }
    t.notes.push_back("not_told_apart: the other exponents whose profile interval reaches below the top of the best's (95 % "
                      "intervals overlapping), which these seeds cannot tell from the best; the best is only as sure as that. "
                      "For k as a continuous interval, --k-range (the transition model on the response curves)");
    return t;
}

}  // namespace demscale::report
