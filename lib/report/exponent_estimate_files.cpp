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

namespace {

// Which of the similarity groups' exponents an interval holds.
std::string groups_inside(const stats::Interval& ci) {
    std::string in, out;
    for (double k : {1.0, 2.0, 3.0}) {
        std::string& list = ci.contains(k) ? in : out;
        list += (list.empty() ? "" : ", ") + format_short(k);
    }
    return "inside the interval: k = " + (in.empty() ? "none" : in) + "; outside: k = " + (out.empty() ? "none" : out);
}

}  // namespace

std::string describe_fit(const stats::TransitionFit& f, const stats::PassingRange* pass, double tolerance) {
    std::string s = std::string(f.sf == 0 ? "all S_f" : "S_f = " + format_short(f.sf, 3)) + ": k-hat = " + format_short(f.k, 3) + " [" + format_short(f.ci.low, 3) + ", " + format_short(f.ci.high, 3) + "]" + " (" + std::to_string(f.standing) +
                    " standing, " + std::to_string(f.slumped) + " slumped runs)";
    if (f.determined && f.extrapolated)
        s += " EXTRAPOLATED (at k-hat most coarse levels lie beyond the fine ones, where the branch is extrapolated; rerun with --offset " +
             format_short(f.k, 2) + ")";
    if (!f.determined)
        return s + " UNDETERMINED (the likelihood does not close inside k = -2 to 6: the coarse levels do not overlap the fine "
                   "curve where it changes; move --range or --offset)";
    s += "; " + groups_inside(f.ci);
    if (pass) {
        auto end = [](double k, bool open, const char* sign) { return std::string(open ? sign : "") + format_short(k, 3); };
        s += "; slump within ±" + format_short(100 * tolerance, 3) + " % of the fill height for k " +
             (pass->empty() ? std::string("- none for every k in the interval (it is wider than the band)")
                            : end(pass->over_interval.low, pass->low_open, "<=") + " to " + end(pass->over_interval.high, pass->high_open, ">=")) +
             " (at k-hat exactly: " + end(pass->at_k_hat.low, pass->low_open, "<=") + " to " + end(pass->at_k_hat.high, pass->high_open, ">=") + ")";
    }
    return s;
}

io::Table response_table(const slump::ResponseStudy& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Response of the slump test to surface tension, per scale factor (" + scene_label + ")";
    t.metadata = {{"scene", scene_label}};
    t.columns = {"sf", "gamma_n_per_m", "seeds", "slump_over_height", "slump_low", "slump_high", "spread_over_d0",
                 "spread_low", "spread_high", "at_rest", "seeds_split", "standing", "slumped_mean"};
    auto add = [&](const slump::ResponseEnsemble& e) {
        if (const auto why = e.unusable(); !why.empty()) {  // not a point of the curve
            std::vector<io::Cell> row(t.columns.size(), io::Cell(io::not_available));
            row[0] = e.sf, row[1] = e.gamma > 0 ? io::Cell(e.gamma) : io::Cell(io::not_available);
            row[2] = static_cast<double>(e.measured.size()), row[9] = "UNUSABLE fill";
            t.rows.push_back(std::move(row));
            // The reason goes to the notes: in the column it would widen the printed table past any screen.
            t.notes.push_back("UNUSABLE fill at S_f " + format_short(e.sf, 3) + ", gamma " + format_short(e.gamma, 4) + " N/m, " + why + " (level not judged)");
            return;
        }
        const auto& s = e.slump_over_height;
        const auto& d = e.spread_over_diameter;
        std::size_t rest = 0;
        std::size_t standing = 0, slumped = 0;
        double slumped_sum = 0;
        for (const auto& r : e.measured) {
            rest += r.at_rest;
            if (r.slump_over_height < study.stands_below) standing++;
            else slumped++, slumped_sum += r.slump_over_height;
        }
        const bool wet_level = e.gamma > 0;
        t.rows.push_back({e.sf, wet_level ? io::Cell(e.gamma) : io::Cell(io::not_available), static_cast<double>(e.measured.size()), s.mean,
                          s.ci.low, s.ci.high, d.mean, d.ci.low, d.ci.high,
                          std::to_string(rest) + " of " + std::to_string(e.measured.size()), split_label(study, e),
                          wet_level ? io::Cell(static_cast<double>(standing)) : io::Cell(io::not_available),
                          wet_level && slumped > 0 ? io::Cell(slumped_sum / static_cast<double>(slumped)) : io::Cell(io::not_available)});
    };
    for (const auto& e : study.fine) add(e);
    for (const auto& levels : study.coarse)
        for (const auto& e : levels) add(e);
    for (const auto& e : study.dry_control) add(e);
    t.notes.push_back("means over the seeds with 95 % Student t intervals; d0: the cone's bottom diameter");
    if (study.has_control()) t.notes.push_back("rows without a surface tension after the levels: the dry control (no liquid), fine then each S_f");
    if (study.wet) t.notes.push_back("coarse levels: gamma is the coarse run's own surface tension (gamma-bar)");
    if (!study.split.empty()) t.notes.push_back(split_note);
    if (study.wet)
        t.notes.push_back("standing: seeds whose column slumped less than " + format_short(study.stands_below, 3) +
                          " of its fill height; slumped_mean: the mean slump of the others");
    return t;
}

io::Table exponent_estimate_table(const slump::ResponseStudy& study, const std::string& scene_label) {
    io::Table t;
    t.title = "Measured exponent k-hat of gamma-bar = gamma S_f^k, from the response curves (" + scene_label + ")";
    t.metadata = {{"decides", "the transition model (probit of standing against ln gamma - k ln S_f, and the slumped runs' branch; 95 % "
                              "interval: the profile likelihood's, widened to the seed jackknife's where that is wider; "
                              "docs/exponent-estimate.md)"},
                  {"beside it", "the means shift: least-squares shift of the coarse means onto the fine curve, 95 % bootstrap over seeds"}};
    t.columns = {"sf", "method", "comparison", "k_hat", "k_low", "k_high", "determined", "k_pass_low", "k_pass_high", "k_pass_low_at_k_hat",
                 "k_pass_high_at_k_hat", "standing_runs", "slumped_runs", "dry_offset_pct_of_height", "split_levels", "rms_at_k_hat",
                 "rms_at_k1", "rms_at_k2", "rms_at_k3", "groups_inside", "k_low_profile", "k_high_profile", "jackknife_se", "extrapolated"};
    t.headings = {"S_f", "method", "comparison", "k̂", "k low (95 %)", "k high (95 %)", "determined", "k passing from", "k passing to",
                  "k passing from (at k̂)", "k passing to (at k̂)", "standing runs", "slumped runs", "dry offset, % of fill height",
                  "split levels", "rms at k̂", "rms at k = 1", "rms at k = 2", "rms at k = 3", "similarity groups inside the interval",
                  "k low (profile)", "k high (profile)", "seed jackknife se of k̂", "extrapolated"};
    const bool corrected = study.has_control();
    const std::string decisive = corrected ? "baseline-corrected" : "raw";
    auto groups_in = [](const stats::Interval& ci, bool determined) {
        std::string inside;
        for (const auto& g : groups)
            if (ci.contains(g.k)) inside += (inside.empty() ? "" : ", ") + std::string(g.name) + " k = " + format_short(g.k);
        return !determined ? std::string("undetermined") : inside.empty() ? std::string("none") : inside;
    };
    const io::Cell na(io::not_available);
    auto model_rows = [&](const std::vector<stats::TransitionFit>& fits, const std::string& comparison, bool with_ranges) {
        for (std::size_t i = 0; i < fits.size(); ++i) {
            const auto& f = fits[i];
            const stats::PassingRange* p = with_ranges && i < study.passing.size() ? &study.passing[i] : nullptr;
            auto end = [&](double k, bool open) { return p && !open && !p->empty() ? io::Cell(k) : na; };
            const double offset = f.sf != 0 && !f.offsets.empty() && corrected && comparison != "raw" ? f.offsets.front() : NAN;
            t.rows.push_back({f.sf == 0 ? io::Cell("all") : io::Cell(f.sf), "transition model", comparison, f.k, f.ci.low, f.ci.high,
                              f.determined ? "yes" : "no", p ? end(p->over_interval.low, p->low_open) : na,
                              p ? end(p->over_interval.high, p->high_open) : na, p && !p->low_open ? io::Cell(p->at_k_hat.low) : na,
                              p && !p->high_open ? io::Cell(p->at_k_hat.high) : na, static_cast<double>(f.standing),
                              static_cast<double>(f.slumped), std::isnan(offset) ? na : io::Cell(100 * offset), na, na, na, na, na,
                              groups_in(f.ci, f.determined), f.profile_ci.low, f.profile_ci.high,
                              std::isnan(f.jackknife_se) ? na : io::Cell(f.jackknife_se), f.extrapolated ? "yes" : "no"});
        }
    };
    auto shift_rows = [&](const std::vector<stats::ExponentEstimate>& estimates, const std::string& comparison, bool with_control) {
        for (const auto& e : estimates) {
            auto cs = curves_of(study, e);
            auto fine = study.fine_curve;
            if (!with_control) {
                fine.control = {};
                for (auto& c : cs) c.control = {};
            }
            t.rows.push_back({sf_label(e), "means shift", comparison, e.k, e.ci.low, e.ci.high, e.determined ? "yes" : "no", na, na, na, na,
                              na, na, e.sf == 0 || !with_control ? na : io::Cell(100 * e.offset), static_cast<double>(e.split_levels), e.rms,
                              stats::shift_residual_rms(fine, cs, 1), stats::shift_residual_rms(fine, cs, 2),
                              stats::shift_residual_rms(fine, cs, 3), groups_in(e.ci, e.determined), na, na, na, na});
        }
    };
    model_rows(study.fits, decisive, true);
    if (corrected) model_rows(study.raw_fits, "raw", false);
    shift_rows(study.estimates, decisive, corrected);
    if (corrected) shift_rows(study.raw_estimates, "raw", false);
    t.notes.push_back("sf 'all': one k for every scale factor together; the first rows (transition model, " + decisive + ") decide");
    if (corrected)
        t.notes.push_back("baseline-corrected: each coarse curve less the dry control's offset (dry coarse - dry fine slump over fill "
                          "height, same seeds), so that what S_f changes without liquid is not read as a shift in k; raw: without it");
    t.notes.push_back("k passing: the k whose coarse slump the model puts within the scene's slump tolerance of the fine one, for every k in "
                      "the interval (from, to) and at k-hat exactly; n/a where the band reaches the end of the fine levels (open) or "
                      "nothing passes for the whole interval");
    t.notes.push_back("standing runs: slump below " + format_short(study.stands_below, 3) + " of the fill height; rms (means shift): root mean square difference of the coarse "
                      "means from the shifted fine curve");
    t.notes.push_back("k low, k high (model): the profile likelihood interval (k low/high profile) or k-hat +- t jackknife_se, whichever "
                      "reaches further on each side; jackknife_se: k-hat's spread when one seed's runs (every level and the dry control) "
                      "are left out at a time");
    t.notes.push_back("extrapolated: at k-hat most of a coarse curve's slumped runs lie beyond the fine levels, where the branch is an "
                      "extrapolated polynomial; the interval is then not trusted: rerun with --offset near k-hat");
    t.notes.push_back("groups: stress similarity (Eq. 11) k = 1, Bond number F/(m g) k = 2, Table 1's force scaling k = 3");
    t.notes.push_back("split_levels (means shift): the levels it rests on whose seeds split between the ends of the response; its bootstrap "
                      "interval then understates the uncertainty (the transition model counts such runs as standing and slumped)");
    if (study.second_look.any()) t.notes.push_back(study.second_look.describe());
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

// The transition model's curves as gnuplot functions of γ (fine, or collapsed γ̄ / S_f^k̂).
std::string model_functions(const stats::TransitionFit& f) {
    std::ostringstream s;
    s << "theta = " << format_number(std::isnan(f.threshold) ? 0.0 : f.threshold) << "; width = " << format_number(std::isnan(f.width) ? 1.0 : f.width)
      << "; centre = " << format_number(f.centre) << "\n";
    s << "p_stand(g) = " << (std::isnan(f.threshold) ? (f.standing > 0 && f.slumped == 0 ? "1" : "0") : "0.5*erfc(-(log(g)-theta)/width/sqrt(2))") << "\n";
    s << "branch(g) = ";
    for (std::size_t j = 0; j < f.branch.size(); ++j) s << (j ? " + " : "") << "(" << format_number(f.branch[j]) << ")*(log(g)-centre)**" << j;
    if (f.branch.empty()) s << "NaN";
    s << "\nmean_response(g) = (1-p_stand(g))*branch(g) + p_stand(g)*" << format_number(f.standing_slump) << "\n";
    return s.str();
}

std::string figure_script(const slump::ResponseStudy& study, const std::string& label) {
    const stats::TransitionFit& fit = study.fits.back();
    const double k_hat = fit.k;
    std::vector<double> sfs = {1};
    for (const auto& c : study.coarse_curves) sfs.push_back(c.sf);
    auto offset_of = [&](std::size_t i) { return i == 0 || fit.offsets.size() < i ? 0.0 : fit.offsets[i - 1]; };
    std::ostringstream s;
    s << "# Generated by demscale: response curves, raw and collapsed, the transition model's two parts, and k's profiles\n"
         "if (!exists(\"outfile\")) outfile = 'estimate_collapse.png'\n"
         "set terminal pngcairo size 1500,1250 enhanced font 'DejaVu Sans,11'\nset output outfile\n"
         "set datafile separator comma\nset datafile columnheaders\nset grid lc rgb '#dddddd'\n"
         "set key top right box opaque\n"
      << model_functions(fit)
      << "set multiplot layout 3,3 title \"Slump response to surface tension, " << label
      << "\\n{/*0.85 points: ensembles (bars: 95 % over seeds); collapsed: coarse γ̄ divided by S_f^k; lines: the transition model at k̂ = "
      << format_short(k_hat, 3) << "}\" font ',13'\n"
         "set logscale x\nset ylabel 'slump / fill height'\nset yrange [0:*]\n";
    auto x_of = [&](double sf, const std::string& k_expr) {
        return sf == 1 ? std::string("column(\"gamma_n_per_m\")") : "column(\"gamma_n_per_m\")/" + format_number(sf) + "**(" + k_expr + ")";
    };
    auto name = [](double sf) { return sf == 1 ? std::string("fine") : "S_f = " + format_short(sf, 3); };
    auto panel = [&](const std::string& title, const std::string& k_expr, const std::string& xlabel, bool model) {
        s << "set title '" << title << "'\nset xlabel '" << xlabel << "'\nplot \\\n";
        for (std::size_t i = 0; i < sfs.size(); ++i)
            s << (i ? ", \\\n" : "") << "  'estimate_response.csv' using " << at_sf(sfs[i], x_of(sfs[i], k_expr))
              << ":\"slump_over_height\":\"slump_low\":\"slump_high\" with yerrorbars lw 2 lc " << i + 1 << " pt " << i + 5 << " title '"
              << name(sfs[i]) << "'";
        if (model) s << ", \\\n  mean_response(x) with lines lw 2 lc rgb 'black' title 'model: mean response'";
        s << "\n";
    };
    panel("as run (γ of each run)", "0", "surface tension γ of the run (N/m)", false);
    panel("collapsed at k̂ = " + format_short(k_hat, 3) + " (transition model)", format_number(k_hat), "γ̄ / S_f^k (N/m)", true);
    // The quantal part: the share of seeds standing, and the probit.
    s << "set title 'quantal part: columns that stood (slump < " << format_short(study.stands_below, 3) << " H_0)'\nset xlabel 'γ̄ / S_f^{k̂} (N/m)'\nset ylabel 'share standing'\n"
         "set yrange [-0.05:1.05]\nplot \\\n";
    for (std::size_t i = 0; i < sfs.size(); ++i)
        s << (i ? ", \\\n" : "") << "  'estimate_response.csv' using " << at_sf(sfs[i], x_of(sfs[i], format_number(k_hat)))
          << ":(column(\"standing\")/column(\"seeds\")) with points pt " << i + 5 << " ps 1.5 lc " << i + 1 << " title '" << name(sfs[i]) << "'";
    s << ", \\\n  p_stand(x) with lines lw 2 lc rgb 'black' title 'probit'\n";
    // The continuous part: the slumped runs' mean, the dry offset removed, and the branch.
    s << "set title 'continuous part: the runs that slumped (dry offset removed)'\nset ylabel 'slump / fill height'\nset yrange [*:*]\nplot \\\n";
    for (std::size_t i = 0; i < sfs.size(); ++i)
        s << (i ? ", \\\n" : "") << "  'estimate_response.csv' using " << at_sf(sfs[i], x_of(sfs[i], format_number(k_hat)))
          << ":(column(\"slumped_mean\") - " << format_number(offset_of(i)) << ") with points pt " << i + 5 << " ps 1.5 lc " << i + 1
          << " title '" << name(sfs[i]) << "'";
    s << ", \\\n  branch(x) with lines lw 2 lc rgb 'black' title 'slumped branch'\nset yrange [0:*]\n";
    for (const auto& g : groups)
        panel("collapsed at k = " + format_short(g.k) + " (" + g.name + ")", format_number(g.k), "γ̄ / S_f^k (N/m)", false);
    s << "unset logscale x\nset title 'means shift: residual against k'\nset xlabel 'exponent k'\n"
         "set ylabel 'rms residual (slump / fill height)'\nplot \\\n";
    for (std::size_t i = 1; i < sfs.size(); ++i)
        s << (i > 1 ? ", \\\n" : "") << "  'estimate_residual.csv' using \"k\":\"rms_sf" << format_short(sfs[i], 3)
          << "\" with lines lw 2 lc " << i + 1 << " title 'S_f = " << format_short(sfs[i], 3) << "'";
    if (sfs.size() > 2) s << ", \\\n  'estimate_residual.csv' using \"k\":\"rms_all\" with lines lw 3 lc rgb 'black' title 'all'";
    // The deviance is known on the search grid only (steps of 0.1): points joined by lines, and the
    // printed interval (profile, widened by the jackknife) as a bar, so the V is not read as the interval.
    s << "\nset title 'profile deviance (grid 0.1); bar: joint 95 % interval'\n"
         "set ylabel '2 (ℓ(k̂) − ℓ(k))'\nset yrange [0:20]\n"
      << "set xrange [" << format_number(std::floor(10 * (k_hat - 0.5)) / 10) << ":" << format_number(std::ceil(10 * (k_hat + 0.5)) / 10) << "]\n"
      << "set arrow 1 from " << format_number(fit.ci.low) << ",1 to " << format_number(fit.ci.high)
      << ",1 heads size 0.03,90 lw 3 lc rgb 'black' front\nplot \\\n";
    for (std::size_t i = 1; i < sfs.size(); ++i)
        s << (i > 1 ? ", \\\n" : "") << "  'estimate_residual.csv' using \"k\":\"deviance_sf" << format_short(sfs[i], 3)
          << "\" with linespoints pt 7 ps 0.5 lw 2 lc " << i + 1 << " title 'S_f = " << format_short(sfs[i], 3) << "'";
    if (sfs.size() > 2) s << ", \\\n  'estimate_residual.csv' using \"k\":\"deviance_all\" with linespoints pt 7 ps 0.6 lw 3 lc rgb 'black' title 'all'";
    s << ", \\\n  " << format_number(fit.cutoff) << " with lines dt 2 lc rgb 'gray40' title '95 % cutoff'\nunset multiplot\n";
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
    write("estimate_runs.csv", io::render(slump::runs_table(slump::response_runs(study), scene_label), io::Format::csv));
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
    for (const auto& fit : study.fits) residual.columns.push_back(fit.sf == 0 ? "deviance_all" : "deviance_sf" + format_short(fit.sf, 3));
    for (std::size_t i = 0; i < study.fits.front().profile_k.size(); ++i) {  // the transition model's grid
        const double k = study.fits.front().profile_k[i];
        if (k < -1 - 1e-9 || k > 6 + 1e-9) continue;
        std::vector<io::Cell> row = {k};
        for (const auto& c : study.coarse_curves) row.push_back(stats::shift_residual_rms(study.fine_curve, {c}, k));
        if (study.coarse_curves.size() > 1) row.push_back(stats::shift_residual_rms(study.fine_curve, study.coarse_curves, k));
        for (const auto& fit : study.fits) row.push_back(fit.profile_deviance[i]);
        residual.rows.push_back(std::move(row));
    }
    write("estimate_residual.csv", io::render(residual, io::Format::csv));
    write("estimate_collapse.gp", figure_script(study, io::gnuplot_literal(scene_label)));
    if (render_png) {
        f.figure_png = out_dir / "estimate_collapse.png";
        io::render_gnuplot(out_dir / "estimate_collapse.gp", f.figure_png);
        f.written.push_back(f.figure_png);
    }
    return f;
}

}  // namespace demscale::report
