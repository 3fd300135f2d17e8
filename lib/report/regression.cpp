#include "report/regression.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
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

// "key: value" metadata lines, in file order.
std::vector<std::pair<std::string, std::string>> metadata(const io::CsvData& d) {
    std::vector<std::pair<std::string, std::string>> m;
    for (const auto& line : d.comments)
        if (const auto colon = line.find(": "); colon != std::string::npos) m.emplace_back(line.substr(0, colon), line.substr(colon + 2));
    return m;
}

std::vector<MetadataChange> compare_metadata(const io::CsvData& ref, const io::CsvData& got) {
    const auto a = metadata(ref), b = metadata(got);
    auto find = [](const auto& m, const std::string& key) -> std::optional<std::string> {
        for (const auto& [k, v] : m)
            if (k == key) return v;
        return std::nullopt;
    };
    std::vector<MetadataChange> changes;
    auto note = [&](const std::string& key) {
        const auto x = find(a, key), y = find(b, key);
        if (x == y) return;
        for (const auto& c : changes)
            if (c.key == key) return;
        changes.push_back({key, x.value_or("(absent)"), y.value_or("(absent)"), key == "demscale" || key == "inputs"});
    };
    for (const auto& [k, v] : a) note(k);
    for (const auto& [k, v] : b) note(k);
    std::stable_partition(changes.begin(), changes.end(), [](const MetadataChange& c) { return !c.informational; });
    return changes;
}
}  // namespace

bool Comparison::inputs_changed() const {
    return std::any_of(changed_inputs.begin(), changed_inputs.end(), [](const MetadataChange& m) { return !m.informational; });
}

Comparison compare_csv(const io::CsvData& ref, const io::CsvData& got, const Tolerance& tol,
                       const std::vector<std::string>& key_columns) {
    Comparison c;
    c.changed_inputs = compare_metadata(ref, got);
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
            for (std::size_t kj : key_index) {  // numbers as people write them: 3.84, not 3.8400000000000003
                double v;
                const std::string& cell = ref.rows[i][kj];
                d.key += (d.key.empty() ? "" : " ") + ref.header[kj] + "=" + (parse_double(cell, v) ? format_short(v, 10) : cell);
            }
            if (c.values_compared++ == 0 || d.excess > c.worst.excess) c.worst = d;
            if (d.excess > 1.0) c.failures.push_back(std::move(d));
        }
    }
    std::stable_sort(c.failures.begin(), c.failures.end(),
                     [](const Deviation& x, const Deviation& y) { return x.excess > y.excess; });
    for (const auto& d : c.failures) {  // worst first, so each column's first failure is its largest excess
        auto it = std::find_if(c.columns.begin(), c.columns.end(), [&](const ColumnSummary& s) { return s.column == d.column; });
        if (it == c.columns.end()) c.columns.push_back({d.column, 0, d}), it = c.columns.end() - 1;
        ++it->outside;
        if (d.relative > it->largest.relative) it->largest = d;
    }
    std::stable_sort(c.columns.begin(), c.columns.end(),
                     [](const ColumnSummary& x, const ColumnSummary& y) { return x.outside > y.outside; });
    return c;
}

std::string describe(const Comparison& c, const std::string& name, const Tolerance& tol, std::size_t max_rows) {
    std::ostringstream out;
    char buf[512];
    const std::string tolerance_text = "|computed - reference| <= " + format_number(tol.absolute) + " + " +
                                       format_number(tol.relative) + " |reference|";
    const bool failed = !c.passed();
    if (!c.changed_inputs.empty()) {
        out << (failed ? "FAIL " : "ok   ") << name << ": " << (c.inputs_changed() ? "inputs changed" : "metadata changed")
            << " (reference -> computed)\n";
        for (const auto& m : c.changed_inputs)
            out << "  " << m.key << ": " << m.reference << " -> " << m.computed << (m.informational ? "  (informational)" : "") << "\n";
    }
    if (!c.problem.empty()) {
        out << "FAIL " << name << ": " << c.problem << "\n";
        return out.str();
    }
    if (c.failures.empty()) {
        std::snprintf(buf, sizeof buf, "%s %s: %zu values within %s (worst: %s, %s, |d| = %.3g, %.3g of tolerance)\n",
                      failed ? "    " : "ok  ", name.c_str(), c.values_compared, tolerance_text.c_str(), c.worst.key.c_str(),
                      c.worst.column.c_str(), c.worst.absolute, c.worst.excess);
        out << buf;
        return out.str();
    }
    out << "FAIL " << name << ": " << c.failures.size() << " of " << c.values_compared << " values outside "
        << tolerance_text << "\n";
    std::snprintf(buf, sizeof buf, "  %-20s %-9s %-14s %s\n", "column", "outside", "largest rel", "at");
    out << buf;
    for (const auto& s : c.columns) {
        std::snprintf(buf, sizeof buf, "  %-20s %-9zu %-14.3g %s (line %d)\n", s.column.c_str(), s.outside, s.largest.relative,
                      s.largest.key.c_str(), s.largest.line);
        out << buf;
    }
    out << "  worst values:\n";
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
