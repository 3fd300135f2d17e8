#include "report/table_layout.hpp"

#include <algorithm>

#include "core/input_error.hpp"

namespace demscale::report {

namespace {
constexpr std::size_t header_wrap = 12;  // headers wrap (CSS overflow-wrap) to about this width
constexpr std::size_t long_text = 40;    // longer text cells wrap inside a column of about this width
constexpr std::size_t padding = 2;

std::size_t column_width(const io::Table& t, std::size_t j) {
    std::size_t w = std::min(t.columns[j].size(), header_wrap);
    for (const auto& row : t.rows)
        if (j < row.size()) w = std::max(w, std::min(document_cell(row[j]).size(), long_text));
    return w + padding;
}

io::Table transposed(const io::Table& t) {
    io::Table out;
    out.title = t.title;
    out.metadata = t.metadata;
    out.notes = t.notes;
    out.columns.push_back(t.columns.front());
    for (const auto& row : t.rows) out.columns.push_back(document_cell(row.front()));
    for (std::size_t j = 1; j < t.columns.size(); ++j) {
        std::vector<io::Cell> r{t.columns[j]};
        for (const auto& row : t.rows) r.push_back(row[j]);
        out.rows.push_back(std::move(r));
    }
    return out;
}

// How many leading columns identify a row (their cells distinct across rows), at most three:
// each part of a split table repeats them.
std::size_t key_columns(const io::Table& t) {
    for (std::size_t k = 1; k <= std::min<std::size_t>(3, t.columns.size() - 1); ++k) {
        std::vector<std::string> keys;
        for (const auto& row : t.rows) {
            std::string key;
            for (std::size_t j = 0; j < k; ++j) key += document_cell(row[j]) + "\x1f";
            keys.push_back(key);
        }
        std::sort(keys.begin(), keys.end());
        if (std::adjacent_find(keys.begin(), keys.end()) == keys.end()) return k;
    }
    return 1;
}

std::vector<io::Table> split_columns(const io::Table& t, std::size_t max_chars) {
    const std::size_t keys = key_columns(t);
    std::size_t key_width = 0;
    for (std::size_t j = 0; j < keys; ++j) key_width += column_width(t, j);
    std::vector<std::vector<std::size_t>> groups;
    std::size_t used = max_chars;  // forces a first group
    for (std::size_t j = keys; j < t.columns.size(); ++j) {
        const std::size_t w = column_width(t, j);
        if (used + w > max_chars) {
            groups.emplace_back();
            for (std::size_t k = 0; k < keys; ++k) groups.back().push_back(k);
            used = key_width;
        }
        groups.back().push_back(j);
        used += w;
    }
    std::vector<io::Table> parts;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        io::Table p;
        p.title = t.title + " (part " + std::to_string(g + 1) + " of " + std::to_string(groups.size()) + ")";
        if (g == 0) p.metadata = t.metadata;
        if (g + 1 == groups.size()) p.notes = t.notes;
        for (std::size_t j : groups[g]) p.columns.push_back(t.columns[j]);
        for (const auto& row : t.rows) {
            std::vector<io::Cell> r;
            for (std::size_t j : groups[g]) r.push_back(row[j]);
            p.rows.push_back(std::move(r));
        }
        parts.push_back(std::move(p));
    }
    return parts;
}
}  // namespace

std::string document_cell(const io::Cell& c) {
    if (const auto* s = std::get_if<std::string>(&c)) return *s;
    return format_short(std::get<double>(c), 4);
}

std::size_t estimated_width(const io::Table& t) {
    std::size_t w = 0;
    for (std::size_t j = 0; j < t.columns.size(); ++j) w += column_width(t, j);
    return w;
}

std::vector<io::Table> fit_to_width(const io::Table& t, std::size_t max_chars) {
    if (t.columns.size() < 2 || estimated_width(t) <= max_chars) return {t};
    // Transposed, each row becomes a column headed by its first cell: only when those are distinct.
    std::vector<std::string> heads;
    for (const auto& row : t.rows) heads.push_back(document_cell(row.front()));
    std::sort(heads.begin(), heads.end());
    const bool distinct = std::adjacent_find(heads.begin(), heads.end()) == heads.end();
    if (!t.rows.empty() && distinct && t.rows.size() < t.columns.size()) {
        io::Table tt = transposed(t);
        if (estimated_width(tt) <= max_chars) return {tt};
    }
    return split_columns(t, max_chars);
}

}  // namespace demscale::report
