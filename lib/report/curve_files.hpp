// Writes one figure's curve files: CSV data, gnuplot script and (optionally) the PNG, each atomically.
// Also recomputes both figures against committed references for CI (`demscale regress`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/table_config.hpp"
#include "report/curves.hpp"
#include "report/regression.hpp"

namespace demscale::report {

struct CurveFiles {
    std::filesystem::path csv, script, png;  // png empty when not rendered
    std::vector<Collapse> collapse;
};

// File stem: "fig3" / "fig4".
std::string figure_stem(Figure figure);

CurveFiles write_curve_files(const io::TableConfig& c, Figure figure, const std::vector<double>& exponents,
                             const std::filesystem::path& out_dir, bool render_png);

// The curve CSV text exactly as `write_curve_files` and the references hold it.
std::string curve_csv(const io::TableConfig& c, Figure figure, const std::vector<double>& exponents);

struct RegressionOutcome {
    std::string report;      // printable
    bool passed = true;
};

// Compares fig3.csv and fig4.csv in reference_dir with freshly computed curves (exponents from the
// config). Throws InputError (exit 2) when a reference is missing or ill-formed. With update = true,
// rewrites the references instead and reports what changed.
RegressionOutcome run_regression(const io::TableConfig& c, const std::filesystem::path& reference_dir,
                                 const Tolerance& tolerance, bool update);

}  // namespace demscale::report
