// Subcommands of the similarity study: table, curves, regress, scaling.
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "core/input_error.hpp"
#include "report/curve_files.hpp"
#include "report/similarity_table.hpp"
#include "similarity/scaling_choice.hpp"

namespace demscale::cli {

namespace {

struct Options {
    std::string config, scene;  // both empty: data/table1.toml
    std::string exponents;
    std::string format = "text";
    int figure = 3;
    std::string out_dir = default_plots;
    bool no_png = false;
    std::string reference_dir = default_references;
    report::Tolerance tolerance;
    bool update = false;
    double s_length = 1, s_density = 1, s_time = 1;
    std::vector<std::string> keep, hold;
};

std::vector<double> exponents_or_config(const Options& o, const io::TableConfig& c) {
    return o.exponents.empty() ? c.exponents : parse_exponents(o.exponents);
}

int run_table(const Options& o) {
    const auto config = similarity_inputs(o.config, o.scene);
    const auto format = io::parse_format(o.format, "--format");
    const auto ks = exponents_or_config(o, config);
    std::vector<io::Table> tables{report::similarity_table(config, ks)};
    if (format != io::Format::csv) tables.push_back(report::similarity_groups_table(ks));
    std::cout << join_tables(tables, format);
    return 0;
}

int run_curves(const Options& o) {
    const auto config = similarity_inputs(o.config, o.scene);
    const auto fig = o.figure == 3 ? report::Figure::force : report::Figure::stress;
    const auto files = report::write_curve_files(config, fig, exponents_or_config(o, config), o.out_dir, !o.no_png);
    std::cout << "wrote " << files.csv.string() << "\nwrote " << files.script.string() << "\n";
    if (!files.png.empty()) std::cout << "wrote " << files.png.string() << "\n";
    for (const auto& c : files.collapse)
        std::printf("collapse %-14s k = %-4s max relative spread between radii: %.3g%s\n",
                    std::string(to_string(c.variant)).c_str(),
                    fig == report::Figure::force ? "-" : format_number(c.exponent).c_str(), c.max_relative_spread,
                    c.max_relative_spread < 1e-9 ? "  (curves collapse)" : "");
    return 0;
}

int run_regress(const Options& o) {
    const auto config = similarity_inputs(o.config, o.scene);
    const auto outcome = report::run_regression(config, o.reference_dir, o.tolerance, o.update);
    std::cout << outcome.report;
    if (outcome.passed) return 0;
    // The hint repeats the user's own inputs, so that updating rewrites the references they compared with.
    std::string command = "demscale regress";
    if (!o.config.empty()) command += " --config '" + o.config + "'";
    if (!o.scene.empty()) command += " --scene '" + o.scene + "'";
    if (o.reference_dir != default_references) command += " --reference-dir '" + o.reference_dir + "'";
    std::cout << "curves drifted from the references; if the change is intended, run `" << command << " --update` and commit "
              << display_path(o.reference_dir) << "/\n";
    return 1;
}

int run_scaling(const Options& o) {
    similarity::ScalingChoice choice;
    choice.basis = o.keep.empty() ? similarity::ScaleBasis{o.s_length, o.s_density, o.s_time}
                                  : similarity::basis_keeping(o.s_length, o.keep[0], o.keep[1]);
    choice.held = o.hold;
    io::Table t;
    t.title = "Scale factors of every DEM quantity (dimension L^a rho^b T^c)";
    t.metadata = {{"basis", "S_L = " + format_number(choice.basis.length) + ", S_rho = " + format_number(choice.basis.density) +
                                ", S_T = " + format_number(choice.basis.time)}};
    t.columns = {"quantity", "unit", "a_length", "b_density", "c_time", "required_factor", "applied_factor", "status"};
    std::size_t broken = 0;
    for (const auto& s : similarity::evaluate_scaling(choice)) {
        const auto& q = *s.quantity;
        broken += s.broken;
        t.rows.push_back({std::string(q.key), std::string(q.si_unit), q.dimension.length, q.dimension.density,
                          q.dimension.time, s.required, s.applied,
                          std::string(s.broken ? "BROKEN (held)" : s.held ? "held, kept" : "scaled")});
    }
    t.notes.push_back(broken == 0 ? "exact similarity: every quantity scales as its dimension demands"
                                  : std::to_string(broken) + " similarity condition(s) broken by held quantities");
    std::cout << io::render(t, io::parse_format(o.format, "--format"));
    return 0;
}

}  // namespace

std::vector<Command> similarity_commands(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto config = [&](CLI::App* s) {
        s->add_option("--config", o->config, "Table 1 style inputs (default: data/table1.toml unless --scene)");
        s->add_option("--scene", o->scene, "a slump scene: its particle, liquid, bridge and [similarity] section give the inputs");
    };
    auto format = [&](CLI::App* s) { s->add_option("--format", o->format, "text | csv | markdown | json")->capture_default_str(); };

    auto* table = app.add_subcommand("table", "Table 1 and the derived similarity table for each radius and exponent");
    config(table);
    table->add_option("--exponent,--exponents", o->exponents, "surface-tension exponents k in gamma S_f^k (default from --config or --scene: 1,3)");
    format(table);

    auto* curves = app.add_subcommand("curves", "the curves of Fig. 3 (force) or Fig. 4 (stress): CSV, gnuplot script, PNG");
    curves->add_option("--figure", o->figure, "3 (F^ vs h^) or 4 (stress vs h^ per exponent)")->check(CLI::IsMember({3, 4}));
    config(curves);
    curves->add_option("--exponent,--exponents", o->exponents, "exponents for Fig. 4 (default from --config or --scene: 1,3)");
    curves->add_option("--out", o->out_dir, "output directory (default: plots/)");
    curves->add_flag("--no-png", o->no_png, "write CSV and gnuplot script only");

    auto* regress = app.add_subcommand("regress", "recompute Figs. 3-4 and compare with data/reference (CI)");
    config(regress);
    regress->add_option("--reference-dir", o->reference_dir, "folder with fig3.csv and fig4.csv (default: data/reference)");
    regress->add_option("--rtol", o->tolerance.relative, "relative tolerance")->capture_default_str()->check(finite_non_negative);
    regress->add_option("--atol", o->tolerance.absolute, "absolute tolerance")->capture_default_str()->check(finite_non_negative);
    regress->add_flag("--update", o->update, "rewrite the references on purpose");

    auto* scaling = app.add_subcommand("scaling", "similarity algebra: scale factor of every DEM quantity for a basis");
    scaling->add_option("--length", o->s_length, "S_L, length scale factor")->capture_default_str();
    scaling->add_option("--density", o->s_density, "S_rho (ignored with --keep)")->capture_default_str();
    scaling->add_option("--time", o->s_time, "S_T (ignored with --keep)")->capture_default_str();
    scaling->add_option("--keep", o->keep, "two quantities whose physical value fixes S_rho and S_T, e.g. gravity,density")
        ->delimiter(',')->expected(2);
    scaling->add_option("--hold", o->hold, "quantities held at their physical value (partial similarity)")->delimiter(',');
    format(scaling);

    return {{table, [o] { return run_table(*o); }},
            {curves, [o] { return run_curves(*o); }},
            {regress, [o] { return run_regress(*o); }},
            {scaling, [o] { return run_scaling(*o); }}};
}

}  // namespace demscale::cli
