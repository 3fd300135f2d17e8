#include "io/table_format.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/input_error.hpp"

namespace demscale::io {

namespace {

std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

std::string cell_text(const Cell& c, bool exact) {
    if (const double* x = std::get_if<double>(&c)) return exact ? format_number(*x) : short_number(*x);
    return std::get<std::string>(c);
}

std::string csv_quote(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return q + "\"";
}

std::string render_text(const Table& t) {
    std::ostringstream out;
    if (!t.title.empty()) out << t.title << "\n";
    for (const auto& [k, v] : t.metadata) out << "  " << k << ": " << v << "\n";
    out << "\n";
    std::vector<std::size_t> width(t.columns.size());
    for (std::size_t j = 0; j < t.columns.size(); ++j) width[j] = t.columns[j].size();
    for (const auto& row : t.rows)
        for (std::size_t j = 0; j < row.size(); ++j) width[j] = std::max(width[j], cell_text(row[j], false).size());
    // Blocks of columns that fit a terminal, each repeating the first (identifying) column.
    constexpr std::size_t max_width = 110;
    std::vector<std::vector<std::size_t>> blocks{{0}};
    std::size_t used = width.empty() ? 0 : width[0];
    for (std::size_t j = 1; j < t.columns.size(); ++j) {
        if (used + 2 + width[j] > max_width && blocks.back().size() > 1) {
            blocks.push_back({0});
            used = width[0];
        }
        blocks.back().push_back(j);
        used += 2 + width[j];
    }
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        if (b) out << "\n";
        auto line = [&](auto&& text_of) {
            for (std::size_t n = 0; n < blocks[b].size(); ++n) {
                const std::size_t j = blocks[b][n];
                const std::string s = text_of(j);
                out << (n ? "  " : "") << std::string(width[j] - s.size(), ' ') << s;
            }
            out << "\n";
        };
        line([&](std::size_t j) { return t.columns[j]; });
        for (const auto& row : t.rows) line([&](std::size_t j) { return cell_text(row[j], false); });
    }
    for (const auto& n : t.notes) out << "  note: " << n << "\n";
    return out.str();
}

std::string render_csv(const Table& t) {
    std::ostringstream out;
    if (!t.title.empty()) out << "# " << t.title << "\n";
    for (const auto& [k, v] : t.metadata) out << "# " << k << ": " << v << "\n";
    for (const auto& n : t.notes) out << "# note: " << n << "\n";
    for (std::size_t j = 0; j < t.columns.size(); ++j) out << (j ? "," : "") << t.columns[j];
    out << "\n";
    for (const auto& row : t.rows) {
        for (std::size_t j = 0; j < row.size(); ++j) out << (j ? "," : "") << csv_quote(cell_text(row[j], true));
        out << "\n";
    }
    return out.str();
}

// Characters as a reader counts them (UTF-8 continuation bytes do not add width).
std::size_t display_width(const std::string& s) {
    std::size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
}

// Padded so that the table also reads as plain text: numbers right-aligned, text left-aligned.
std::string render_markdown(const Table& t) {
    std::ostringstream out;
    if (!t.title.empty()) out << "### " << t.title << "\n\n";
    for (const auto& [k, v] : t.metadata) out << "- **" << k << "**: " << v << "\n";
    const std::size_t n = t.columns.size();
    std::vector<std::size_t> width(n);
    std::vector<bool> numeric(n, true);
    for (std::size_t j = 0; j < n; ++j) width[j] = std::max<std::size_t>(3, display_width(t.columns[j]));
    for (const auto& row : t.rows)
        for (std::size_t j = 0; j < row.size() && j < n; ++j) {
            width[j] = std::max(width[j], display_width(cell_text(row[j], false)));
            numeric[j] = numeric[j] && std::holds_alternative<double>(row[j]);
        }
    auto cell = [&](const std::string& text, std::size_t j) {
        const std::string pad(width[j] - display_width(text), ' ');
        out << " " << (numeric[j] ? pad + text : text + pad) << " |";
    };
    out << "\n|";
    for (std::size_t j = 0; j < n; ++j) cell(t.columns[j], j);
    out << "\n|";
    for (std::size_t j = 0; j < n; ++j)
        out << (numeric[j] ? std::string(width[j] + 1, '-') + ":|" : ":" + std::string(width[j] + 1, '-') + "|");
    out << "\n";
    for (const auto& row : t.rows) {
        out << "|";
        for (std::size_t j = 0; j < row.size() && j < n; ++j) cell(cell_text(row[j], false), j);
        out << "\n";
    }
    if (!t.notes.empty()) out << "\n";
    for (const auto& note : t.notes) out << "> note: " << note << "\n";
    return out.str();
}

std::string render_json(const Table& t) {
    nlohmann::ordered_json j;
    j["title"] = t.title;
    j["metadata"] = nlohmann::ordered_json::object();
    for (const auto& [k, v] : t.metadata) j["metadata"][k] = v;
    j["columns"] = t.columns;
    j["rows"] = nlohmann::ordered_json::array();
    for (const auto& row : t.rows) {
        nlohmann::ordered_json r;
        for (std::size_t c = 0; c < row.size(); ++c) {
            // A number that does not exist ("n/a" in text) is null, so a column keeps one type.
            if (const double* x = std::get_if<double>(&row[c])) r[t.columns[c]] = *x;
            else if (std::get<std::string>(row[c]) == not_available) r[t.columns[c]] = nullptr;
            else r[t.columns[c]] = std::get<std::string>(row[c]);
        }
        j["rows"].push_back(r);
    }
    j["notes"] = t.notes;
    return j.dump(2) + "\n";
}

}  // namespace

Format parse_format(const std::string& text, const std::string& field) {
    if (text == "text") return Format::text;
    if (text == "csv") return Format::csv;
    if (text == "markdown") return Format::markdown;
    if (text == "json") return Format::json;
    throw InputError(field, "\"" + text + "\"", "one of text, csv, markdown, json");
}

std::string render(const Table& table, Format format) {
    switch (format) {
        case Format::text: return render_text(table);
        case Format::csv: return render_csv(table);
        case Format::markdown: return render_markdown(table);
        case Format::json: return render_json(table);
    }
    return {};
}

}  // namespace demscale::io
