// demscale — command-line front end. Parses arguments, calls lib/, prints. No physics here.
// Exit codes: 0 success, 1 regression drift, 2 bad input, 3 runtime failure (I/O, gnuplot).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/input_error.hpp"
#include "core/version.hpp"
#include "io/table_config.hpp"
#include "io/table_format.hpp"
#include "report/curve_files.hpp"
#include "report/similarity_table.hpp"
#include "similarity/scaling_choice.hpp"

namespace ds = demscale;

namespace {

constexpr const char* default_config = DEMSCALE_SOURCE_DIR "/data/table1.toml";
constexpr const char* default_plots = DEMSCALE_SOURCE_DIR "/plots";
constexpr const char* default_references = DEMSCALE_SOURCE_DIR "/data/reference";

// "1,3" → {1, 3}; every item a finite number in (−20, 20).
std::vector<double> parse_exponents(const std::string& text) {
    std::vector<double> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, end - start);
        char* stop = nullptr;
        const double k = std::strtod(item.c_str(), &stop);
        if (item.empty() || stop != item.c_str() + item.size() || !(k > -20 && k < 20))
            throw ds::InputError("--exponent", "\"" + item + "\"", "comma-separated numbers in (-20, 20), e.g. 1,3");
        out.push_back(k);
        start = end + 1;
    }
    return out;
}

// Inputs are named relative to the source tree when they live in it, so shipped outputs do not
// carry one machine's absolute paths.
ds::io::TableConfig load_config(const std::string& path) {
    auto c = ds::io::load_table_config(path);
    const std::string root = std::string(DEMSCALE_SOURCE_DIR) + "/";
    if (c.source.rfind(root, 0) == 0) c.source = c.source.substr(root.size());
    return c;
}

std::string join_tables(const std::vector<ds::io::Table>& tables, ds::io::Format format) {
    if (format == ds::io::Format::json) {
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const auto& t : tables) all.push_back(nlohmann::ordered_json::parse(ds::io::render(t, format)));
        return all.dump(2) + "\n";
    }
    std::string s;
    for (const auto& t : tables) s += (s.empty() ? "" : "\n") + ds::io::render(t, format);
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"demscale: similarity (scaling) laws for DEM of wet granular material (Yun & Park 2017)"};
    app.set_version_flag("--version", std::string(ds::version));
    app.require_subcommand(1);

    std::string config_path = default_config;
    std::string exponents_text;
    std::string format_text = "text";

    auto* table = app.add_subcommand("table", "Table 1 and the derived similarity table for each radius and exponent");
    table->add_option("--config", config_path, "TOML inputs (default: data/table1.toml)");
    table->add_option("--exponent", exponents_text, "surface-tension exponents k in gamma S_f^k (default from config: 1,3)");
    table->add_option("--format", format_text, "text | csv | markdown | json")->capture_default_str();

    int figure = 3;
    std::string out_dir = default_plots;
    bool no_png = false;
    auto* curves = app.add_subcommand("curves", "the curves of Fig. 3 (force) or Fig. 4 (stress): CSV, gnuplot script, PNG");
    curves->add_option("--figure", figure, "3 (F^ vs h^) or 4 (stress vs h^ per exponent)")->check(CLI::IsMember({3, 4}));
    curves->add_option("--config", config_path, "TOML inputs (default: data/table1.toml)");
    curves->add_option("--exponent", exponents_text, "exponents for Fig. 4 (default from config: 1,3)");
    curves->add_option("--out", out_dir, "output directory (default: plots/)");
    curves->add_flag("--no-png", no_png, "write CSV and gnuplot script only");

    std::string reference_dir = default_references;
    ds::report::Tolerance tolerance;
    bool update = false;
    auto* regress = app.add_subcommand("regress", "recompute Figs. 3-4 and compare with data/reference (CI)");
    regress->add_option("--config", config_path, "TOML inputs (default: data/table1.toml)");
    regress->add_option("--reference-dir", reference_dir, "folder with fig3.csv and fig4.csv (default: data/reference)");
    regress->add_option("--rtol", tolerance.relative, "relative tolerance")->capture_default_str()->check(CLI::NonNegativeNumber);
    regress->add_option("--atol", tolerance.absolute, "absolute tolerance")->capture_default_str()->check(CLI::NonNegativeNumber);
    regress->add_flag("--update", update, "rewrite the references on purpose");

    double s_length = 1, s_density = 1, s_time = 1;
    std::vector<std::string> keep, hold;
    bool list = false;
    auto* scaling = app.add_subcommand("scaling", "similarity algebra: scale factor of every DEM quantity for a basis");
    scaling->add_option("--length", s_length, "S_L, length scale factor")->capture_default_str();
    scaling->add_option("--density", s_density, "S_rho (ignored with --keep)")->capture_default_str();
    scaling->add_option("--time", s_time, "S_T (ignored with --keep)")->capture_default_str();
    scaling->add_option("--keep", keep, "two quantities whose physical value fixes S_rho and S_T, e.g. gravity,density")
        ->delimiter(',')->expected(2);
    scaling->add_option("--hold", hold, "quantities held at their physical value (partial similarity)")->delimiter(',');
    scaling->add_option("--format", format_text, "text | csv | markdown | json")->capture_default_str();
    scaling->add_flag("--list", list, "list the quantity catalogue");

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "demscale: error: " << e.what() << "\n";
        return 2;
    }

    try {
        const auto format = ds::io::parse_format(format_text, "--format");
        if (*table) {
            auto config = load_config(config_path);
            const auto ks = exponents_text.empty() ? config.exponents : parse_exponents(exponents_text);
            std::vector<ds::io::Table> tables{ds::report::similarity_table(config, ks)};
            if (format != ds::io::Format::csv) tables.push_back(ds::report::similarity_groups_table(ks));
            std::cout << join_tables(tables, format);
        } else if (*curves) {
            auto config = load_config(config_path);
            const auto ks = exponents_text.empty() ? config.exponents : parse_exponents(exponents_text);
            const auto fig = figure == 3 ? ds::report::Figure::force : ds::report::Figure::stress;
            const auto files = ds::report::write_curve_files(config, fig, ks, out_dir, !no_png);
            std::cout << "wrote " << files.csv.string() << "\nwrote " << files.script.string() << "\n";
            if (!files.png.empty()) std::cout << "wrote " << files.png.string() << "\n";
            for (const auto& c : files.collapse)
                std::printf("collapse %-14s k = %-4s max relative spread between radii: %.3g%s\n",
                            std::string(to_string(c.variant)).c_str(),
                            fig == ds::report::Figure::force ? "-" : ds::format_number(c.exponent).c_str(),
                            c.max_relative_spread, c.max_relative_spread < 1e-9 ? "  (curves collapse)" : "");
        } else if (*regress) {
            auto config = load_config(config_path);
            const auto outcome = ds::report::run_regression(config, reference_dir, tolerance, update);
            std::cout << outcome.report;
            if (!outcome.passed) {
                std::cout << "curves drifted from the references; if the change is intended, run "
                             "`demscale regress --update` and commit data/reference/\n";
                return 1;
            }
        } else if (*scaling) {
            ds::similarity::ScalingChoice choice;
            if (!keep.empty()) choice.basis = ds::similarity::basis_keeping(s_length, keep[0], keep[1]);
            else choice.basis = {s_length, s_density, s_time};
            choice.held = hold;
            ds::io::Table t;
            t.title = list ? "Quantity catalogue (dimension L^a rho^b T^c)" : "Scale factors under the chosen basis";
            t.metadata = {{"basis", "S_L = " + ds::format_number(choice.basis.length) + ", S_rho = " +
                                        ds::format_number(choice.basis.density) + ", S_T = " +
                                        ds::format_number(choice.basis.time)}};
            t.columns = {"quantity", "unit", "a_length", "b_density", "c_time", "required_factor", "applied_factor", "status"};
            std::size_t broken = 0;
            for (const auto& s : ds::similarity::evaluate_scaling(choice)) {
                const auto& q = *s.quantity;
                const std::string status = s.broken ? "BROKEN (held)" : s.held ? "held, kept" : "scaled";
                broken += s.broken;
                t.rows.push_back({std::string(q.key), std::string(q.si_unit), q.dimension.length, q.dimension.density,
                                  q.dimension.time, s.required, s.applied, status});
            }
            t.notes.push_back(broken == 0 ? "exact similarity: every quantity scales as its dimension demands"
                                          : std::to_string(broken) + " similarity condition(s) broken by held quantities");
            std::cout << ds::io::render(t, format);
        }
    } catch (const ds::InputError& e) {
        std::cerr << "demscale: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "demscale: failed: " << e.what() << "\n";
        return 3;
    }
    return 0;
}
