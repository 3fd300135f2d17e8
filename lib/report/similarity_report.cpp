#include "report/similarity_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <memory>
#include <optional>

#include "bridge/bridge_model.hpp"
#include "bridge/liquid_volume.hpp"
#include "dem/bridge_law.hpp"
#include "core/input_error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "io/table_config.hpp"
#include "report/bridge_error.hpp"
#include "report/bridge_error_files.hpp"
#include "report/curve_files.hpp"
#include "report/caveats.hpp"
#include "report/document.hpp"
#include "report/exponent_estimate_files.hpp"
#include "report/scene_table.hpp"
#include "report/similarity_table.hpp"
#include "report/slump_study_files.hpp"
#include "report/slump_study_tables.hpp"
#include "slump/bridge_warnings.hpp"
#include "slump/scene_bridges.hpp"
#include "slump/liggghts_run.hpp"
#include "slump/slump_files.hpp"
#include "slump/study.hpp"
#include "stats/verdict.hpp"

namespace demscale::report {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

std::string pct(double x) { return format_short(100 * x, 3) + " %"; }

io::Table bridge_at_scene(double vhat, ContactAngle theta) {
    const auto exact = bridge::make_bridge_model("exact");
    const std::vector<std::string> names = {"mikami1998", "yun-park-2017"};
    std::vector<std::unique_ptr<bridge::BridgeModel>> models;
    for (const auto& n : names) models.push_back(bridge::make_bridge_model(n));
    io::Table t;
    t.title = "Bridge force at the scene's liquid volume: regressions against the exact Young-Laplace bridge";
    t.metadata = {{"V^", format_short(vhat)}, {"theta_deg", format_short(theta.degrees())},
                  {"physical bound", "F^ <= cos(theta) = " + format_short(std::cos(theta.radians()))}};
    t.columns = {"hhat", "fhat_exact"};
    for (const auto& n : names) t.columns.push_back("fhat_" + n), t.columns.push_back("error_pct_" + n);
    const double rupture = exact->hhat_rupture(vhat, theta);
    for (double f : {0.0, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8, 0.95}) {
        const double h = f * rupture;
        const double e = exact->fhat(vhat, theta, h);
        std::vector<io::Cell> row = {h, e};
        for (const auto& model : models) {
            const double m = model->fhat(vhat, theta, h);
            row.push_back(m);
            row.push_back(e > 0 ? 100 * (m - e) / e : 0.0);
        }
        t.rows.push_back(std::move(row));
    }
    t.notes.push_back("F^ = F/(2 pi R gamma) for every model (Eq. 1 as printed uses 2 pi R gamma; Mikami's own form pi R gamma)");
    t.notes.push_back("gaps as fractions 0 ... 0.95 of the exact rupture distance h^_c = " + format_short(rupture));
    return t;
}

// "k = 1: PASS at S_f = 1.4; INCONCLUSIVE at S_f = 1.96; FAIL at S_f = 2.74, 3.84. k = 3: ..."
std::string verdicts_by_exponent(const slump::Study& study) {
    std::vector<double> ks;
    for (const auto& v : study.deciding())
        if (std::find(ks.begin(), ks.end(), v.exponent) == ks.end()) ks.push_back(v.exponent);
    std::string text;
    for (double k : ks) {
        text += "k = " + format_short(k) + ":";
        std::string sep = " ";
        for (auto outcome : {stats::Verdict::pass, stats::Verdict::inconclusive, stats::Verdict::fail}) {
            std::string sfs;
            for (const auto& v : study.deciding())
                if (v.exponent == k && v.overall == outcome && v.unusable.empty()) sfs += (sfs.empty() ? "" : ", ") + format_short(v.sf);
            if (!sfs.empty()) text += sep + stats::verdict_name(outcome) + " at S_f = " + sfs, sep = "; ";
        }
        std::string unusable;
        for (const auto& v : study.deciding())
            if (v.exponent == k && !v.unusable.empty()) unusable += (unusable.empty() ? "" : ", ") + format_short(v.sf);
        if (!unusable.empty()) text += sep + "fills unusable (the cone could not hold them) at S_f = " + unusable;
        text += ". ";
    }
    return text;
}

std::string verdict_text(const slump::Study& study, const std::vector<double>& sfs) {
    std::string v;
    const auto& n = study.noise;
    v += "The fine ensemble (" + std::to_string(study.noise.slump_over_height.n) + " seeds) scatters by " +
         pct(n.slump_over_height.sd) + " of the fill height in slump (sd), " +
         pct(n.spread.sd / std::max(n.spread.mean, 1e-300)) + " in spread and " + pct(n.profile.mean) +
         " in profile (each run from the mean shape): differences of that size between single runs are noise. ";
    for (double sf : sfs) {
        const auto& b = study.best_at(sf);
        v += "At S_f = " + format_short(sf) + " the exponent k = " + format_short(b.exponent) +
             " comes closest to the fine ensemble (profile distance " + pct(b.criteria[2].estimate) + ", slump difference " +
             pct(b.criteria[0].estimate) + " of the height, spread difference " + pct(b.criteria[1].estimate) + "): " +
             stats::verdict_name(b.overall) + ". ";
    }
    auto distance = [&](double sf, double k) -> std::optional<double> {
        for (const auto& e : study.deciding())
            if (e.sf == sf && e.exponent == k && e.unusable.empty()) return e.criteria[2].estimate;
        return std::nullopt;
    };
    int compared = 0, k1_better = 0;
    for (double sf : sfs)
        if (const auto e1 = distance(sf, 1.0), e3 = distance(sf, 3.0); e1 && e3) ++compared, k1_better += *e1 < *e3;
    if (compared > 0)
        v += "Yun & Park (2017) prefer k = 1 over k = 3 (Fig. 5, judged by eye); here the k = 1 ensembles are closer in profile at " +
             std::to_string(k1_better) + " of " + std::to_string(compared) + " scale factors.";
    return v;
}

// The measured exponent's section from its study (wet: k-hat, the range of k, the figure; dry: the
// dry control), its answer in the verdict section, and its caveats. wall: the section's seconds.
void add_estimate_section(const slump::ResponseStudy& est, const slump::ResponsePlan& rp, double wall, const std::string& scene_label,
                          const fs::path& figures, Section& section, Section& verdict, std::vector<Caveat>& caveats) {
    std::size_t fine_runs = 0, coarse_runs = 0;
    for (const auto& e : est.fine) fine_runs += e.measured.size();
    for (const auto& levels : est.coarse)
        for (const auto& e : levels) coarse_runs += e.measured.size();
    const auto files = write_estimate_files(est, scene_label, figures, true);
    const std::string cost = "Cost: " + std::to_string(fine_runs) + " fine runs (" + std::to_string(est.fine.size()) + " levels x " +
                             std::to_string(rp.seeds) + " seeds) and " + std::to_string(coarse_runs) + " coarse runs, " +
                             format_short(wall, 3) + " s for this section (cached runs cost nothing).";
    if (!est.wet) {
        section.blocks.push_back(Paragraph{
            "A dry scene has no cohesion to vary. The dry control: coarse against fine, one ensemble each, the error coarse-graining "
            "the dry laws leaves and no exponent can remove (docs/exponent-estimate.md). " + cost});
        section.blocks.push_back(TableBlock{dry_baseline_table(est, scene_label)});
        section.blocks.push_back(TableBlock{response_table(est, scene_label)});
        return;
    }
    section.blocks.push_back(Paragraph{
        "Instead of judging candidate exponents, measure one. The fine scene runs at several surface tensions (factors of the "
        "scene's gamma), each coarse S_f at gamma-bar = the same factors times S_f^" + format_short(rp.offset_exponent) +
        ". If gamma-bar = gamma S_f^k keeps the pile, a coarse run at gamma-bar behaves like a fine one at gamma-bar / S_f^k. "
        "The transition model fits whether each column stood (a probit in ln gamma - k ln S_f) and how far the others slumped "
        "(the slumped branch, less the dry control's offset) in one likelihood; k-hat is its maximum and the 95 % interval its "
        "profile likelihood's. From the fitted curve follows the range of k whose coarse slump stays within the scene's slump "
        "tolerance of the fine one (docs/exponent-estimate.md). " + cost});
    section.blocks.push_back(TableBlock{exponent_estimate_table(est, scene_label)});
    section.blocks.push_back(FigureBlock{files.figure_png, "Slump response to surface tension: raw, collapsed at the "
                                                                    "measured k (with the model's mean response) and at k = 1, 2, 3; "
                                                                    "the model's quantal and continuous parts; the residual and the "
                                                                    "profile deviance against k"});
    section.blocks.push_back(TableBlock{response_table(est, scene_label)});
    std::string answer = "Measured exponent (transition model): ";
    for (std::size_t i = 0; i < est.fits.size(); ++i)
        answer += (i ? "; " : "") + describe_fit(est.fits[i], &est.passing[i], rp.fine.tolerances.slump);
    verdict.blocks.push_back(Paragraph{answer + " (section Measured exponent)."});
    for (const auto& f : est.fits)
        if (!f.determined)
            caveats.push_back({f.sf == 0 ? std::string("all S_f") : "S_f = " + format_short(f.sf),
                               "measured exponent undetermined (the likelihood does not close inside k = -2 to 6)"});
    auto not_at_rest = [&](const slump::ResponseEnsemble& e) {
        const std::string where = "S_f = " + format_short(e.sf) + ", gamma = " + format_short(e.gamma, 3) + " N/m";
        if (!e.all_at_rest()) caveats.push_back({where, "measured exponent: runs not all at rest"});
        if (const auto* split = slump::split_of(est, e))
            caveats.push_back({where, "measured exponent: seeds split (" + std::to_string(split->low) + " low, " +
                                          std::to_string(split->high) + " high of " + std::to_string(split->seeds) +
                                          "): the means shift's bootstrap interval understates the uncertainty (the transition "
                                          "model, which decides, counts them as standing and slumped runs)"});
    };
    for (const auto& e : est.fine) not_at_rest(e);
    for (const auto& levels : est.coarse)
        for (const auto& e : levels) not_at_rest(e);
}

// The study's plan, and the estimate's with --estimate, both checked before any file is written.
slump::StudyPlan study_plan(const ReportOptions& o, const slump::SlumpScene& scene, const std::vector<double>& ks) {
    slump::StudyPlan plan;
    plan.fine = scene;
    plan.exponents = ks;
    plan.scale_factors = o.scale_factors;
    plan.tolerances = scene.tolerances;
    plan.jobs = o.jobs, plan.threads_per_job = o.threads_per_job;
    plan.cache_dir = o.cache_dir;
    plan.slurm = o.slurm;
    plan.seeds = o.seeds;
    plan.baseline = o.baseline;
    plan.live = o.live;
    slump::validate_plan(plan);
    return plan;
}

std::optional<slump::ResponsePlan> response_plan(const ReportOptions& o, const slump::SlumpScene& scene) {
    if (!o.estimate) return std::nullopt;
    slump::ResponsePlan response = *o.estimate;
    response.fine = scene;
    response.batch.jobs = o.jobs, response.batch.threads_per_job = o.threads_per_job, response.batch.cache_dir = o.cache_dir;
    response.batch.slurm = o.slurm;
    response.batch.live = o.live;
    slump::validate_response_plan(response);
    return response;
}

// On Slurm, every slump run of the report goes in one submission and comes back in one call,
// before anything is written; the sections then read them all from the cache.
void run_all_on_slurm(const ReportOptions& o, const slump::StudyPlan& plan, const std::optional<slump::ResponsePlan>& response,
                      const std::function<void(const std::string&)>& say) {
    auto study_runs = slump::plan_study(plan);
    auto all = study_runs.all_runs();
    std::optional<slump::ResponseStudy> response_runs;
    if (response) {
        response_runs = slump::plan_response_runs(*response);
        for (auto* r : response_runs->all_runs()) all.push_back(r);
    }
    slump::run_batch(all, {o.jobs, o.threads_per_job, o.cache_dir, plan.force_dt, plan.fine.radius_m, o.live, o.slurm},
                     [&](const std::string& s) { say("slump: " + s); });
}

Section similarity_section(const io::TableConfig& config, const std::vector<double>& ks) {
    Section similarity{"Similarity table", {}};
    similarity.blocks.push_back(Paragraph{"Table 1 of Yun & Park (2017) recomputed from " + config.source +
                                          ": every scaled radius, its mass, liquid volume (Eq. 5), Mikami coefficients "
                                          "(Eqs. 6-8), contact force and the stress of Eq. 11 for each exponent k."});
    similarity.blocks.push_back(TableBlock{similarity_table(config, ks)});
    similarity.blocks.push_back(Paragraph{"Which similarity groups each candidate exponent keeps (exponent 0) or breaks, from the "
                                          "dimensional algebra of Feng et al. (2009) with S_L = S_f and S_rho = 1:"});
    similarity.blocks.push_back(TableBlock{similarity_groups_table(ks)});
    return similarity;
}

Section curves_section(const io::TableConfig& config, const std::vector<double>& ks, const fs::path& figures) {
    Section curves{"Curves: Figs. 3 and 4", {}};
    for (auto fig : {Figure::force, Figure::stress}) {
        const auto files = write_curve_files(config, fig, ks, figures, true);
        curves.blocks.push_back(FigureBlock{files.png, fig == Figure::force
                                                           ? "Fig. 3: dimensionless capillary force against dimensionless gap, every radius"
                                                           : "Fig. 4: bridge stress of Eq. 11 against dimensionless gap, per exponent k"});
        io::Table c;
        c.title = std::string("Collapse of the ") + (fig == Figure::force ? "Fig. 3" : "Fig. 4") + " curves across radii";
        c.columns = {"variant", "exponent", "max_relative_spread"};
        for (const auto& x : files.collapse)
            c.rows.push_back({std::string(bridge::to_string(x.variant)),
                              fig == Figure::force ? io::Cell(std::string("-")) : io::Cell(x.exponent), x.max_relative_spread});
        c.notes.push_back("(max - min)/max over radii at the same gap; 0 means the curves coincide");
        curves.blocks.push_back(TableBlock{c});
    }
    return curves;
}

Section bridges_section(const ReportOptions& o, const slump::SlumpScene& scene, const fs::path& figures, std::vector<Caveat>& caveats) {
    Section bridges{"Bridge model accuracy", {}};
    const double vhat = slump::bridge_vhat(scene);
    bridges.blocks.push_back(Paragraph{"The scene's liquid gives V^ = " + format_short(vhat) +
                                       " for every S_f (Eq. 5 scales the bridge with the particle mass). The regressions against "
                                       "the exact Young-Laplace bridge there, and over a grid of V^, theta and gap:"});
    bridges.blocks.push_back(TableBlock{bridge_at_scene(vhat, scene.liquid.contact_angle)});
    const auto grid = default_bridge_error_grid(o.quick);
    const auto study = bridge_error_study(grid, o.bridge_table_path, o.quick ? 4 : 16, o.quick ? 5 : 21, o.quick ? 0.02 : 0.2);
    write_bridge_error_files(study, figures, true);
    bridges.blocks.push_back(TableBlock{study.summary});
    bridges.blocks.push_back(FigureBlock{figures / "bridge_mikami_error.png",
                                         "Relative error of Mikami (1998) against the exact bridge over V^ and gap, theta = 0"});
    bridges.blocks.push_back(FigureBlock{figures / "bridge_speed_error.png", "Cost per force evaluation against error, per model"});
    const auto printed = bridge::mikami_coefficients(vhat, scene.liquid.contact_angle, {bridge::MikamiVariant::yun_park_2017});
    const auto published = bridge::mikami_coefficients(vhat, scene.liquid.contact_angle, {bridge::MikamiVariant::mikami1998});
    const double bound = 2 * M_PI * scene.radius_m * scene.liquid.surface_tension_n_per_m * std::cos(scene.liquid.contact_angle.radians());
    const double f_printed = bridge::bridge_force_newton(printed, bridge::mikami_fhat(printed, 0), scene.radius_m,
                                                         scene.liquid.surface_tension_n_per_m);
    const double f_published = bridge::bridge_force_newton(published, bridge::mikami_fhat(published, 0), scene.radius_m,
                                                           scene.liquid.surface_tension_n_per_m);
    bridges.blocks.push_back(Paragraph{
        "Printed against published Mikami: at contact, R = " + format_short(scene.radius_m * 1e3) + " mm, the paper's printed form "
        "(2 pi R gamma, C = 0.042) gives F = " + format_short(f_printed * 1e3) + " mN; Mikami's published form (pi R gamma) gives " +
        format_short(f_published * 1e3) + " mN; no sphere-sphere bridge can exceed 2 pi R gamma cos(theta) = " +
        format_short(bound * 1e3) + " mN. The printed form exceeds the bound by " + pct(f_printed / bound - 1) +
        ", so demscale defaults to the published form" +
        (scene.particle_curve != bridge::CurveSource::fit
             ? ". This scene's DEM bridges follow neither: they take " + std::string(dem::particle_curve_source(scene).label) +
                   " (bridge_variant = " + slump::bridge_variant_name(scene) + "), and the table and curves above show the fit it replaces."
             : " (" + slump::bridge_variant_name(scene) + " in this scene).")});
    // The fits' findings at the scene's V̂ and θ, and with wet walls the wall fit's excess over
    // the exact sphere–plane bridge: what every command that runs the scene prints.
    for (const auto& w : slump::bridge_warnings(scene)) caveats.push_back({"the scene's bridge", w});
    return bridges;
}

// Caveats per ensemble, not per run: how many runs did not come to rest, which geometry limits apply.
void study_caveats(const slump::Study& study, std::vector<Caveat>& caveats) {
    auto ensemble_caveats = [&](const std::string& who, const std::vector<const slump::StudyRun*>& runs) {
        std::size_t moving = 0, unusable = 0;
        for (const auto* r : runs) moving += r->unusable.empty() && !r->result.came_to_rest, unusable += !r->unusable.empty();
        if (moving > 0)
            caveats.push_back({who, "slump: " + std::to_string(moving) + " of " + std::to_string(runs.size()) +
                                        " runs not at rest when the spread time limit ended"});
        if (unusable > 0)
            caveats.push_back({who, "slump: " + std::to_string(unusable) + " of " + std::to_string(runs.size()) +
                                        " fills unusable (the cone could not hold the scene's mass): the ensemble is not judged"});
        for (const auto& w : runs.front()->warnings) caveats.push_back({who, "slump geometry limits similarity: " + w});
    };
    std::vector<const slump::StudyRun*> fine = {&study.reference};
    for (const auto& r : study.replicas) fine.push_back(&r);
    ensemble_caveats("fine", fine);
    for (std::size_t i = 0; i < study.runs.size(); ++i)
        ensemble_caveats("S_f = " + format_short(study.runs[i].grain.sf) + ", k = " + format_short(study.runs[i].grain.exponent),
                         study.coarse_runs(i));
}

// The slump study's section (piles, ensembles, figures, runs) and the verdict section it opens.
void slump_sections(const slump::Study& study, const ReportOptions& o, int seeds, const fs::path& figures, Section& slump_section,
                    Section& verdict_section) {
    slump_section.blocks.push_back(Paragraph{
        "Mini-cone slump test (fill, settle, lift the cone at constant speed, spread until at rest or a time limit). The fine "
        "reference has " + std::to_string(study.reference.result.particles) + " particles; each coarse run fills the same cone "
        "with particles of radius S_f R and surface tension gamma S_f^k, everything else held (time step from the Rayleigh time)."});
    auto side = [&](const slump::StudyRun& r, const std::string& stem, const std::string& what) {
        const auto title = what + ": " + std::to_string(r.result.particles) + " particles, slump " +
                           format_short(r.result.slump() * 1e3, 3) + " mm, spread " + format_short(r.result.final.spread * 1e3, 3) + " mm";
        slump::write_slump_files(r.result, title, figures, stem, true);
        slump_section.blocks.push_back(FigureBlock{figures / (stem + "_side.png"), "Side view of the final pile, " + title, true});
    };
    side(study.reference, "slump_reference", "fine reference (S_f = 1), seed " + std::to_string(study.reference.scene.seed));
    for (const auto& r : study.runs)
        if (r.unusable.empty()) side(r, "slump_sf" + format_short(r.grain.sf) + "_k" + format_short(r.grain.exponent),
             "S_f = " + format_short(r.grain.sf) + ", k = " + format_short(r.grain.exponent) + ", seed " + std::to_string(r.scene.seed));
    const auto files = write_study_files(study, o.scene_label, figures, "study", true);
    slump_section.blocks.push_back(TableBlock{ensemble_table(study, o.scene_label)});
    if (!files.front_png.empty()) {  // none when no ensemble could be judged
        slump_section.blocks.push_back(FigureBlock{files.profiles_png, "Final radial height profiles of the coarse runs over the fine ones"});
        slump_section.blocks.push_back(FigureBlock{files.error_png, "Slump, spread and profile differences against the exponent k, per S_f, with 95 % intervals"});
        slump_section.blocks.push_back(FigureBlock{files.front_png, "Speed against error: profile distance against the particle-step speed-up"});
    }
    slump_section.blocks.push_back(TableBlock{best_exponent_table(study, study.judged_scale_factors())});
    slump_section.blocks.push_back(Paragraph{"Reading the verdict. " + verdict_text(study, study.judged_scale_factors())});
    slump_section.blocks.push_back(TableBlock{study_table(study, o.scene_label)});
    verdict_section.blocks.push_back(Paragraph{
        "Each coarse ensemble (S_f, k) is compared with the fine ensemble, " + std::to_string(seeds) +
        " seeds each, by an equivalence test: PASS where the 95 % interval of the difference lies inside the tolerance, FAIL "
        "where it lies wholly outside, INCONCLUSIVE otherwise (docs/verdicts.md). " +
        (study.has_control() ? std::string("Each is judged twice: raw, and after removing the offset the same S_f shows in the dry "
                                           "control (the same scene and seeds without liquid); the corrected comparison decides, "
                                           "and the dry control's own difference is the row beside. ")
                             : std::string()) +
        verdicts_by_exponent(study)});
    verdict_section.blocks.push_back(TableBlock{verdict_table(study, o.scene_label)});
}

std::string number_list(const std::vector<double>& xs) {
    std::string s;
    for (double x : xs) s += (s.empty() ? "" : ", ") + format_short(x);
    return s;
}

Section inputs_section(const ReportOptions& o, const slump::SlumpScene& scene, const slump::StudyPlan& plan,
                       const std::vector<std::pair<std::string, double>>& timings) {
    Section inputs{"Inputs", {}};
    std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    inputs.blocks.push_back(BulletList{{"demscale " + std::string(version) + (o.git_revision.empty() ? "" : ", git " + o.git_revision),
                                        "generated " + std::string(date) + (o.quick ? " (--quick: coarse grids, fewer seeds and scale factors)" : ""),
                                        "scale factors S_f: " + number_list(o.scale_factors),
                                        "candidate exponents k (gamma = gamma0 S_f^k): " + number_list(plan.exponents),
                                        "seeds per ensemble: " + std::to_string(plan.seeds),
                                        "tolerances: slump " + pct(plan.tolerances.slump) + " of the fill height, spread " + pct(plan.tolerances.spread) +
                                            ", profile " + pct(plan.tolerances.profile)}});
    inputs.blocks.push_back(TableBlock{scene_table(scene, o.scene_label)});
    io::Table time_table;
    time_table.title = "Wall time of each section";
    time_table.columns = {"section", "wall_s"};
    for (const auto& [name, s] : timings) time_table.rows.push_back({name, s});
    inputs.blocks.push_back(TableBlock{time_table});
    return inputs;
}

}  // namespace

ReportOutcome write_similarity_report(const ReportOptions& o, const std::function<void(const std::string&)>& log) {
    const auto start = Clock::now();
    auto say = [&](const std::string& s) {
        if (log) log(s);
    };
    const fs::path figures = o.out_dir / "figures";
    std::vector<std::pair<std::string, double>> timings;
    auto timed = [&](const std::string& name, auto&& work) {
        const auto t0 = Clock::now();
        say(name + " ...");
        work();
        timings.push_back({name, std::chrono::duration<double>(Clock::now() - t0).count()});
    };
    const io::TableConfig& config = o.similarity;
    const auto ks = o.exponents.empty() ? config.exponents : o.exponents;
    auto scene = slump::load_slump_scene(o.scene_path);
    if (o.seed_base > 0) scene.seed = o.seed_base;
    if (o.liggghts_ranks > 0) slump::use_liggghts(scene, o.liggghts_ranks, "--ranks");
    const auto plan = study_plan(o, scene, ks);  // a bad plan is refused before any file is written
    const auto response = response_plan(o, scene);
    if (o.slurm) run_all_on_slurm(o, plan, response, say);

    Document doc;
    doc.title = "demscale similarity report: " + scene.name;
    std::vector<Caveat> caveats;
    Section similarity, curves, bridges, slump_section{"Slump test", {}}, verdict_section{"Verdict", {}}, estimate_section{"Measured exponent", {}};
    timed("similarity table", [&] { similarity = similarity_section(config, ks); });
    timed("curves", [&] { curves = curves_section(config, ks, figures); });
    timed("bridge models", [&] { bridges = bridges_section(o, scene, figures, caveats); });
    timed("slump study", [&] {
        const auto study = slump::run_study(plan, [&](const std::string& s) { say("slump: " + s); });
        slump_sections(study, o, plan.seeds, figures, slump_section, verdict_section);
        study_caveats(study, caveats);
    });
    if (response) timed("measured exponent", [&] {
        const auto t0 = Clock::now();
        const auto est = slump::run_response_study(*response, [&](const std::string& s) { say("estimate: " + s); });
        const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
        add_estimate_section(est, *response, wall, o.scene_label, figures, estimate_section, verdict_section, caveats);
    });
    const Section inputs = inputs_section(o, scene, plan, timings);

    Section caveat_section{"Caveats", {}};
    const auto caveat_lines = grouped_caveats(caveats);
    if (caveat_lines.empty()) caveat_section.blocks.push_back(Paragraph{"None found."});
    else caveat_section.blocks.push_back(BulletList{caveat_lines});
    doc.sections = {verdict_section, inputs, similarity, curves, bridges, slump_section};
    if (response) doc.sections.push_back(estimate_section);
    doc.sections.push_back(caveat_section);

    ReportOutcome out;
    out.html = o.out_dir / "report.html";
    out.markdown = o.out_dir / "report.md";
    io::write_file_atomically(out.markdown, render_markdown(doc, o.out_dir));
    io::write_file_atomically(out.html, render_html(doc));
    out.caveats = caveat_lines;
    out.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
}

}  // namespace demscale::report
