#include "report/table_layout.hpp"

#include <algorithm>
#include <utility>

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

// Unit suffixes of the identifiers, longest first, and the words they stand for.
constexpr std::pair<const char*, const char*> unit_suffixes[] = {
    {"_pct_of_height", " (% of fill height)"}, {"_n_per_m", " (N/m)"}, {"_m_per_s", " (m/s)"}, {"_kg_per_m3", " (kg/m³)"},
    {"_fine_radii", " (fine radii)"}, {"_pct", " (%)"}, {"_mm", " (mm)"}, {"_deg", " (deg)"}, {"_us", " (µs)"}, {"_ms", " (ms)"},
    {"_g", " (g)"}, {"_s", " (s)"}, {"_m", " (m)"}, {"_n", " (N)"}, {"_j", " (J)"}, {"_pa", " (Pa)"}};
// Words the identifiers abbreviate.
constexpr std::pair<const char*, const char*> words[] = {
    {"sf", "S_f"}, {"fhat", "F̂"}, {"hhat", "ĥ"}, {"vhat", "V̂"}, {"k_hat", "k̂"}, {"sd", "sd"}, {"rms", "rms"},
    {"diff", "difference"}, {"d0", "d₀"}, {"r", "R"}};

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool empty_cell(const io::Cell& c) {
    const auto* s = std::get_if<std::string>(&c);
    return s && (s->empty() || *s == io::not_available);
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

std::string heading_of(const std::string& column) {
    std::string stem = column, unit;
    for (const auto& [suffix, text] : unit_suffixes)
        if (ends_with(stem, suffix)) {
            stem.resize(stem.size() - std::string(suffix).size()), unit = text;
            break;
        }
    for (const auto& [id, text] : words)
        if (stem == id) return text + unit;
    std::string out;
    std::size_t start = 0;
    while (start <= stem.size()) {
        const std::size_t end = std::min(stem.find('_', start), stem.size());
        std::string word = stem.substr(start, end - start);
        for (const auto& [id, text] : words)
            if (word == id) word = text;
        out += (out.empty() ? "" : " ") + word;
        start = end + 1;
    }
    return out + unit;
}

io::Table for_people(io::Table t) {
    std::vector<std::string> heads = t.headings.size() == t.columns.size() ? t.headings : std::vector<std::string>{};
    if (heads.empty())
        for (const auto& c : t.columns) heads.push_back(heading_of(c));
    for (auto& n : t.notes)
        for (std::size_t j = 0; j < t.columns.size(); ++j)
            if (n.rfind(t.columns[j] + ":", 0) == 0) n = heads[j] + n.substr(t.columns[j].size());
    std::vector<std::size_t> keep;
    for (std::size_t j = 0; j < t.columns.size(); ++j)
        if (t.rows.empty() || std::any_of(t.rows.begin(), t.rows.end(), [&](const auto& row) { return j < row.size() && !empty_cell(row[j]); }))
            keep.push_back(j);
    io::Table out;
    out.title = std::move(t.title), out.metadata = std::move(t.metadata), out.notes = std::move(t.notes);
    for (std::size_t j : keep) out.columns.push_back(heads[j]);
    for (const auto& row : t.rows) {
        std::vector<io::Cell> r;
        for (std::size_t j : keep) r.push_back(j < row.size() ? row[j] : io::Cell(std::string()));
        out.rows.push_back(std::move(r));
    }
    return out;
}

}  // namespace demscale::report
