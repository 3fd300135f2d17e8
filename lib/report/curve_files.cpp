#include "report/curve_files.hpp"

#include <filesystem>

#include "core/input_error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_reader.hpp"
#include "io/gnuplot.hpp"
#include "report/curve_plots.hpp"

namespace demscale::report {

namespace fs = std::filesystem;

std::string figure_stem(Figure figure) { return figure == Figure::force ? "fig3" : "fig4"; }

std::string curve_csv(const io::TableConfig& c, Figure figure, const std::vector<double>& exponents) {
    return io::render(curves_table(c, figure, compute_curves(c, figure, exponents)), io::Format::csv);
}

CurveFiles write_curve_files(const io::TableConfig& c, Figure figure, const std::vector<double>& exponents,
                             const fs::path& out_dir, bool render_png) {
    const std::string stem = figure_stem(figure);
    const auto points = compute_curves(c, figure, exponents);
    CurveFiles f;
    f.collapse = measure_collapse(points, figure);
    f.csv = out_dir / (stem + ".csv");
    f.script = out_dir / (stem + ".gp");
    io::write_file_atomically(f.csv, io::render(curves_table(c, figure, points), io::Format::csv));
    io::write_file_atomically(f.script, curve_plot_script(c, figure, exponents, stem + ".csv", stem + ".png"));
    if (render_png) {
        f.png = out_dir / (stem + ".png");
        io::render_gnuplot(f.script, f.png);
    }
    return f;
}

RegressionOutcome run_regression(const io::TableConfig& c, const fs::path& reference_dir, const Tolerance& tolerance,
                                 bool update) {
    RegressionOutcome outcome;
    for (Figure figure : {Figure::force, Figure::stress}) {
        const fs::path ref_path = reference_dir / (figure_stem(figure) + ".csv");
        const std::string text = curve_csv(c, figure, c.exponents);
        const io::CsvData computed = io::parse_csv(text, "computed " + figure_stem(figure));
        if (update) {
            std::string change = "new";
            if (fs::exists(ref_path)) {
                const auto cmp = compare_csv(io::read_csv_file(ref_path.string()), computed, tolerance, {});
                std::string inputs;
                for (const auto& m : cmp.changed_inputs)
                    if (!m.informational) inputs += (inputs.empty() ? "" : ", ") + m.key;
                change = (inputs.empty() ? "" : "inputs changed (" + inputs + "); ") +
                         (!cmp.problem.empty()      ? cmp.problem
                          : cmp.failures.empty()    ? std::string("values unchanged within tolerance")
                                                    : std::to_string(cmp.failures.size()) + " values changed");
            }
            io::write_file_atomically(ref_path, text);
            outcome.report += "updated " + ref_path.string() + ": " + change + "\n";
            continue;
        }
        if (!fs::exists(ref_path))
            throw InputError("reference", ref_path.string(),
                             "an existing reference CSV (create it on purpose with `demscale regress --update`)");
        const auto cmp = compare_csv(io::read_csv_file(ref_path.string()), computed, tolerance,
                                     {"variant", "radius_mm", "exponent", "hhat"});
        if (!cmp.problem.empty() && !cmp.inputs_changed())  // not drift: the file is not a curve file of this shape
            throw InputError("reference " + ref_path.string(), cmp.problem,
                             "the columns and rows `demscale curves` writes (regenerate with `demscale regress --update`)");
        outcome.report += describe(cmp, ref_path.string(), tolerance);
        outcome.passed = outcome.passed && cmp.passed();
    }
    return outcome;
}

}  // namespace demscale::report
