#include "report/regression.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/input_error.hpp"

namespace demscale::report {

namespace {
bool parse_double(const std::string& s, double& x) {
    if (s.empty()) return false;
    char* end = nullptr;
    x = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
}
}  // namespace

Comparison compare_csv(const io::CsvData& ref, const io::CsvData& got, const Tolerance& tol,
                       const std::vector<std::string>& key_columns) {
    Comparison c;
    if (ref.header != got.header) {
        std::string missing, extra;
        for (const auto& h : ref.header)
            if (std::find(got.header.begin(), got.header.end(), h) == got.header.end()) missing += " " + h;
        for (const auto& h : got.header)
            if (std::find(ref.header.begin(), ref.header.end(), h) == ref.header.end()) extra += " " + h;
        c.problem = "columns differ (reference lacks:" + (extra.empty() ? std::string(" -") : extra) +
                    "; computed lacks:" + (missing.empty() ? std::string(" -") : missing) + ")";
        return c;
    }
    if (ref.rows.size() != got.rows.size()) {
        c.problem = "row count differs: reference " + std::to_string(ref.rows.size()) + ", computed " +
                    std::to_string(got.rows.size());
        return c;
    }
    std::vector<std::size_t> key_index;
    for (const auto& k : key_columns)
        for (std::size_t j = 0; j < ref.header.size(); ++j)
            if (ref.header[j] == k) key_index.push_back(j);

    for (std::size_t i = 0; i < ref.rows.size(); ++i) {
        for (std::size_t j = 0; j < ref.header.size(); ++j) {
            const std::string& a = ref.rows[i][j];
            const std::string& b = got.rows[i][j];
            Deviation d;
            double x, y;
            if (parse_double(a, x) && parse_double(b, y)) {
                if (!std::isfinite(x) || !std::isfinite(y)) {
                    d.excess = (a == b) ? 0.0 : INFINITY;
                } else {
                    d.absolute = std::abs(y - x);
                    d.relative = x != 0 ? d.absolute / std::abs(x) : (d.absolute > 0 ? INFINITY : 0.0);
                    d.excess = d.absolute / (tol.absolute + tol.relative * std::abs(x));
                }
            } else {
                d.excess = a == b ? 0.0 : INFINITY;
            }
            d.row = i;
            d.line = i < ref.row_lines.size() ? ref.row_lines[i] : 0;
            d.column = ref.header[j];
            d.reference = a;
            d.computed = b;
            for (std::size_t kj : key_index) d.key += (d.key.empty() ? "" : " ") + ref.header[kj] + "=" + ref.rows[i][kj];
            if (c.values_compared++ == 0 || d.excess > c.worst.excess) c.worst = d;
            if (d.excess > 1.0) c.failures.push_back(std::move(d));
        }
    }
    std::stable_sort(c.failures.begin(), c.failures.end(),
                     [](const Deviation& x, const Deviation& y) { return x.excess > y.excess; });
    return c;
}

std::string describe(const Comparison& c, const std::string& name, const Tolerance& tol, std::size_t max_rows) {
    std::ostringstream out;
    char buf[512];
    const std::string tolerance_text = "|computed - reference| <= " + format_number(tol.absolute) + " + " +
                                       format_number(tol.relative) + " |reference|";
    if (!c.problem.empty()) {
        out << "FAIL " << name << ": " << c.problem << "\n";
        return out.str();
    }
    if (c.passed()) {
        std::snprintf(buf, sizeof buf, "ok   %s: %zu values within %s (worst: %s, %s, |d| = %.3g, %.3g of tolerance)\n",
                      name.c_str(), c.values_compared, tolerance_text.c_str(), c.worst.key.c_str(),
                      c.worst.column.c_str(), c.worst.absolute, c.worst.excess);
        out << buf;
        return out.str();
    }
    out << "FAIL " << name << ": " << c.failures.size() << " of " << c.values_compared << " values outside "
        << tolerance_text << "\n";
    std::snprintf(buf, sizeof buf, "  %-6s %-52s %-20s %-22s %-22s %-10s %-10s\n", "line", "row", "column", "reference",
                  "computed", "abs diff", "rel diff");
    out << buf;
    for (std::size_t i = 0; i < std::min(max_rows, c.failures.size()); ++i) {
        const auto& d = c.failures[i];
        std::snprintf(buf, sizeof buf, "  %-6d %-52s %-20s %-22s %-22s %-10.3g %-10.3g\n", d.line, d.key.c_str(),
                      d.column.c_str(), d.reference.c_str(), d.computed.c_str(), d.absolute, d.relative);
        out << buf;
    }
    if (c.failures.size() > max_rows) out << "  ... and " << c.failures.size() - max_rows << " more\n";
    return out.str();
}

}  // namespace demscale::report
