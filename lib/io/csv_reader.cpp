#include "io/csv_reader.hpp"

#include "io/input_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/input_error.hpp"

namespace demscale::io {

namespace {
std::vector<std::string> split_fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted) {
            if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
            else if (ch == '"') quoted = false;
            else out.back() += ch;
        } else if (ch == '"') {
            quoted = true;
        } else if (ch == ',') {
            out.emplace_back();
        } else if (ch != '\r') {
            out.back() += ch;
        }
    }
    return out;
}
}  // namespace

CsvData parse_csv(const std::string& text, const std::string& source) {
    CsvData d;
    std::istringstream in(text);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty()) continue;
        if (line[0] == '#') {
            d.comments.push_back(line.size() > 2 ? line.substr(2) : "");
            continue;
        }
        auto fields = split_fields(line);
        if (d.header.empty()) {
            d.header = std::move(fields);
            continue;
        }
        if (fields.size() != d.header.size())
            throw InputError(source + ":" + std::to_string(n), std::to_string(fields.size()) + " fields",
                             std::to_string(d.header.size()) + " fields, as in the header");
        d.rows.push_back(std::move(fields));
        d.row_lines.push_back(n);
    }
    if (d.header.empty()) throw InputError(source, "(no header row)", "a CSV file with a header row");
    return d;
}

CsvData read_csv_file(const std::string& path) {
    return parse_csv(read_input_file("input file", path, "a readable CSV file"), path);
}

std::optional<double> finite_number(std::string_view field) {
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t')) field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t')) field.remove_suffix(1);
    if (!field.empty() && field.front() == '+') field.remove_prefix(1);
    double x = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), x);
    if (field.empty() || error != std::errc() || end != field.data() + field.size() || !std::isfinite(x)) return std::nullopt;
    return x;
}

}  // namespace demscale::io
