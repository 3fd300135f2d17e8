// gnuplot scripts for the Fig. 3 and Fig. 4 curve files: labelled axes with units, a legend per
// radius, the configured variant solid and the other variant dashed, one panel per exponent (Fig. 4).
#pragma once

#include <string>
#include <vector>

#include "io/table_config.hpp"
#include "report/curves.hpp"

namespace demscale::report {

// csv_name and png_name are file names relative to the script's directory.
std::string curve_plot_script(const io::TableConfig& c, Figure figure, const std::vector<double>& exponents,
                              const std::string& csv_name, const std::string& png_name);

}  // namespace demscale::report
