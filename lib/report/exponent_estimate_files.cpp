#include "report/exponent_estimate_files.hpp"

#include <cmath>
#include <sstream>

#include "core/input_error.hpp"
#include "io/atomic_file.hpp"
#include "io/gnuplot.hpp"

namespace demscale::report {

namespace fs = std::filesystem;

namespace {

// The exponents the similarity algebra gives for the groups a slump test might keep.
struct Group {
    double k;
    const char* name;
};
constexpr Group groups[] = {{1, "stress, Eq. 11"}, {2, "Bond number"}, {3, "Table 1 forces"}};

std::string sf_label(const stats::ExponentEstimate& e) { return e.sf == 0 ? "all" : format_short(e.sf, 3); }

// "no", or "2 low, 4 high": seeds in the lowest and highest third of the span of the level means.
std::string split_label(const slump::ResponseStudy& study, const slump::ResponseEnsemble& e) {
    if (!study.wet) return "-";
    const auto* s = slump::split_of(study, e);
    return s ? std::to_string(s->low) + " low, " + std::to_string(s->high) + " high" : "no";
}

constexpr const char* split_note =
    "seeds_split: seeds in the lowest and in the highest third of the span of all level means (a column that stood and one that "
    "slumped at the same surface tension); the bootstrap interval of an estimate resting on such a level understates its "
    "uncertainty: more seeds there (docs/exponent-estimate.md)";

std::vector<stats::ResponseCurve> curves_of(const slump::ResponseStudy& s, const stats::ExponentEstimate& e) {
    if (e.sf == 0) return s.coarse_curves;
    for (const auto& c : s.coarse_curves)
        if (c.sf == e.sf) return {c};
    return {};
}

}  // namespace

io::Table response_table(const slump::ResponseStudy& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Response of the slump test to surface tension, per scale factor (" + scene_label + ")";
    t.metadata = {{"scene", scene_label}};
    t.columns = {"sf", "gamma_n_per_m", "seeds", "slump_over_height", "slump_low", "slump_high", "spread_over_d0",
                 "spread_low", "spread_high", "at_rest", "seeds_split"};
    auto add = [&](const slump::ResponseEnsemble& e) {
        if (const auto why = e.unusable(); !why.empty()) {  // not a point of the curve
            std::vector<io::Cell> row(t.columns.size(), io::Cell(io::not_available));
            row[0] = e.sf, row[1] = e.gamma > 0 ? io::Cell(e.gamma) : io::Cell(io::not_available);
            row[2] = static_cast<double>(e.runs.size()), row[9] = "UNUSABLE fill, " + why;
            t.rows.push_back(std::move(row));
            return;
        }
        const auto& s = e.slump_over_height;
        const auto& d = e.spread_over_diameter;
        std::size_t rest = 0;
        for (const auto& r : e.runs) rest += r.result.came_to_rest;
        t.rows.push_back({e.sf, e.gamma > 0 ? io::Cell(e.gamma) : io::Cell(io::not_available), static_cast<double>(e.runs.size()), s.mean,
                          s.ci.low, s.ci.high, d.mean, d.ci.low, d.ci.high,
                          std::to_string(rest) + " of " + std::to_string(e.runs.size()), split_label(study, e)});
    };
    for (const auto& e : study.fine) add(e);
    for (const auto& levels : study.coarse)
        for (const auto& e : levels) add(e);
    for (const auto& e : study.dry_control) add(e);
    t.notes.push_back("means over the seeds with 95 % Student t intervals; d0: the cone's bottom diameter");
    if (study.has_control()) t.notes.push_back("rows without a surface tension after the levels: the dry control (no liquid), fine then each S_f");
    if (study.wet) t.notes.push_back("coarse levels: gamma is the coarse run's own surface tension (gamma-bar)");
    if (!study.split.empty()) t.notes.push_back(split_note);
    return t;
}

io::Table exponent_estimate_table(const slump::ResponseStudy& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Measured exponent k-hat of gamma-bar = gamma S_f^k, from the shift of the response curves (" + scene_label + ")";
    t.metadata = {{"estimator", "least-squares shift of the coarse means onto the fine curve (monotone cubic through the fine means, "
                                "flat beyond), k = shift / ln S_f; 95 % percentile bootstrap over seeds (docs/exponent-estimate.md)"}};
    t.columns = {"sf", "comparison", "k_hat", "k_low", "k_high", "dry_offset_pct_of_height", "determined", "split_levels", "rms_at_k_hat",
                 "rms_at_k1", "rms_at_k2", "rms_at_k3", "groups_inside"};
    t.headings = {"S_f", "comparison", "k̂", "k low (95 %)", "k high (95 %)", "dry offset, % of fill height", "determined",
                  "split levels", "rms at k̂", "rms at k = 1", "rms at k = 2", "rms at k = 3", "similarity groups inside the interval"};
    t.metadata.push_back({"decides", study.has_control() ? "baseline-corrected: the dry control's coarse - fine offset subtracted"
                                                         : "raw (no dry control: --baseline none)"});
    auto rows = [&](const std::vector<stats::ExponentEstimate>& estimates, const std::string& comparison, bool with_control) {
        for (const auto& e : estimates) {
            auto cs = curves_of(study, e);
            auto fine = study.fine_curve;
            if (!with_control) {
                fine.control = {};
                for (auto& c : cs) c.control = {};
            }
            std::string inside;
            for (const auto& g : groups)
                if (e.ci.contains(g.k)) inside += (inside.empty() ? "" : ", ") + std::string(g.name) + " k = " + format_short(g.k);
            if (!e.determined) inside = "undetermined: no unique shift maps the curves onto each other";
            else if (inside.empty()) inside = "none";
            t.rows.push_back({sf_label(e), comparison, e.k, e.ci.low, e.ci.high,
                              e.sf == 0 || !with_control ? io::Cell(io::not_available) : io::Cell(100 * e.offset),
                              e.determined ? "yes" : "no", static_cast<double>(e.split_levels), e.rms,
                              stats::shift_residual_rms(fine, cs, 1), stats::shift_residual_rms(fine, cs, 2),
                              stats::shift_residual_rms(fine, cs, 3), inside});
        }
    };
    rows(study.estimates, study.has_control() ? "baseline-corrected" : "raw", study.has_control());
    if (study.has_control()) rows(study.raw_estimates, "raw", false);
    t.notes.push_back("sf 'all': one k for every scale factor together");
    if (study.has_control())
        t.notes.push_back("baseline-corrected: each coarse curve less the dry control's offset (dry coarse - dry fine slump over fill "
                          "height, same seeds), so that what S_f changes without liquid is not read as a shift in k; raw: without it");
    t.notes.push_back("rms: root mean square difference of the coarse means (slump over fill height) from the shifted fine curve");
    t.notes.push_back("groups: stress similarity (Eq. 11) k = 1, Bond number F/(m g) k = 2, Table 1's force scaling k = 3");
    t.notes.push_back("split_levels: the levels it rests on whose seeds split between the ends of the response (response table, "
                      "seeds_split); with any, the interval understates the uncertainty");
    return t;
}

io::Table dry_baseline_table(const slump::ResponseStudy& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Dry control: coarse minus fine, the error coarse-graining leaves without any liquid (" + scene_label + ")";
    t.columns = {"sf", "slump_diff_pct_of_height", "slump_low_pct", "slump_high_pct", "spread_diff_pct", "spread_low_pct",
                 "spread_high_pct", "profile_distance_pct", "profile_low_pct", "profile_high_pct", "fine_noise_slump_pct",
                 "fine_noise_spread_pct", "fine_noise_profile_pct", "within_noise"};
    for (const auto& b : study.baselines) {
        std::vector<io::Cell> row = {b.sf};
        for (const auto& c : b.criteria) row.push_back(100 * c.estimate), row.push_back(100 * c.interval.low), row.push_back(100 * c.interval.high);
        const auto& n = b.noise;
        row.push_back(100 * n.slump_over_height.sd);
        row.push_back(100 * n.spread.sd / n.spread.mean);
        row.push_back(100 * n.profile.mean);
        const bool within = b.criteria[0].interval.contains(0) && b.criteria[1].interval.contains(0) &&
                            b.criteria[2].interval.high <= n.profile.mean;
        row.push_back(within ? "yes: no difference at 95 %" : "no: a baseline error");
        t.rows.push_back(std::move(row));
    }
    t.notes.push_back("95 % intervals as check-exponent's (docs/verdicts.md): Welch t for slump and spread, bootstrap for the "
                      "profile distance; noise: the fine ensemble's own (sd over seeds; profile: each run from the mean shape)");
    return t;
}

namespace {

std::string at_sf(double sf, const std::string& x) {
    return "(abs(column(\"sf\") - " + format_number(sf) + ") < 1e-9 ? " + x + " : NaN)";
}

std::string figure_script(const slump::ResponseStudy& study, const std::string& label, double k_hat) {
    std::vector<double> sfs = {1};
    for (const auto& c : study.coarse_curves) sfs.push_back(c.sf);
    std::ostringstream s;
    s << "# Generated by demscale: response curves, raw and collapsed, and the residual against k\n"
         "if (!exists(\"outfile\")) outfile = 'estimate_collapse.png'\n"
         "set terminal pngcairo size 1500,900 enhanced font 'DejaVu Sans,11'\nset output outfile\n"
         "set datafile separator comma\nset datafile columnheaders\nset grid lc rgb '#dddddd'\n"
         "set key top right box opaque\n"
      << "set multiplot layout 2,3 title \"Slump response to surface tension, " << label
      << "\\n{/*0.85 bars: 95 % intervals over seeds; collapsed: coarse γ̄ divided by S_f^k}\" font ',13'\n"
         "set logscale x\nset ylabel 'slump / fill height'\nset yrange [0:*]\n";
    auto panel = [&](const std::string& title, const std::string& k_expr, const std::string& xlabel) {
        s << "set title '" << title << "'\nset xlabel '" << xlabel << "'\nplot \\\n";
        for (std::size_t i = 0; i < sfs.size(); ++i) {
            const double sf = sfs[i];
            const std::string x = sf == 1 ? "column(\"gamma_n_per_m\")" : "column(\"gamma_n_per_m\")/" + format_number(sf) + "**(" + k_expr + ")";
            s << (i ? ", \\\n" : "") << "  'estimate_response.csv' using " << at_sf(sf, x)
              << ":\"slump_over_height\":\"slump_low\":\"slump_high\" with yerrorlines lw 2 lc " << i + 1 << " pt " << i + 5
              << " title '" << (sf == 1 ? "fine" : "S_f = " + format_short(sf, 3)) << "'";
        }
        s << "\n";
    };
    panel("as run (γ of each run)", "0", "surface tension γ of the run (N/m)");
    panel("collapsed at the measured k = " + format_short(k_hat, 3), format_number(k_hat), "γ̄ / S_f^k (N/m)");
    for (const auto& g : groups)
        panel("collapsed at k = " + format_short(g.k) + " (" + g.name + ")", format_number(g.k), "γ̄ / S_f^k (N/m)");
    s << "unset logscale x\nset yrange [0:*]\nset title 'residual against k'\nset xlabel 'exponent k'\n"
         "set ylabel 'rms residual (slump / fill height)'\nplot \\\n";
    for (std::size_t i = 1; i < sfs.size(); ++i)
        s << (i > 1 ? ", \\\n" : "") << "  'estimate_residual.csv' using \"k\":\"rms_sf" << format_short(sfs[i], 3)
          << "\" with lines lw 2 lc " << i + 1 << " title 'S_f = " << format_short(sfs[i], 3) << "'";
    if (sfs.size() > 2) s << ", \\\n  'estimate_residual.csv' using \"k\":\"rms_all\" with lines lw 3 lc rgb 'black' title 'all'";
    s << "\nunset multiplot\n";
    return s.str();
}

}  // namespace

EstimateFiles write_estimate_files(const slump::ResponseStudy& study, const std::string& scene_label, const fs::path& out_dir,
                                   bool render_png) {
    EstimateFiles f;
    auto write = [&](const std::string& name, const std::string& text) {
        io::write_file_atomically(out_dir / name, text);
        f.written.push_back(out_dir / name);
    };
    write("estimate_response.csv", io::render(response_table(study, scene_label), io::Format::csv));
    if (!study.wet) {
        write("estimate_dry_control.csv", io::render(dry_baseline_table(study, scene_label), io::Format::csv));
        return f;
    }
    write("estimate_exponent.csv", io::render(exponent_estimate_table(study, scene_label), io::Format::csv));
    io::Table residual;
    residual.title = "Residual of the shifted fine curve against k (" + scene_label + ")";
    residual.columns = {"k"};
    for (const auto& c : study.coarse_curves) residual.columns.push_back("rms_sf" + format_short(c.sf, 3));
    if (study.coarse_curves.size() > 1) residual.columns.push_back("rms_all");
    for (int i = 0; i <= 140; ++i) {
        const double k = -1 + 0.05 * i;
        std::vector<io::Cell> row = {k};
        for (const auto& c : study.coarse_curves) row.push_back(stats::shift_residual_rms(study.fine_curve, {c}, k));
        if (study.coarse_curves.size() > 1) row.push_back(stats::shift_residual_rms(study.fine_curve, study.coarse_curves, k));
        residual.rows.push_back(std::move(row));
    }
    write("estimate_residual.csv", io::render(residual, io::Format::csv));
    write("estimate_collapse.gp", figure_script(study, io::gnuplot_literal(scene_label), study.estimates.back().k));
    if (render_png) {
        f.figure_png = out_dir / "estimate_collapse.png";
        io::render_gnuplot(out_dir / "estimate_collapse.gp", f.figure_png);
        f.written.push_back(f.figure_png);
    }
    return f;
}

}  // namespace demscale::report
