// One in-memory table, four renderings: aligned text, CSV, Markdown, JSON. Every rendering carries
// the metadata (variant, version, inputs) — as `#` lines above the CSV header, a bullet list in
// Markdown, an object in JSON — so a table explains itself wherever it ends up.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace demscale::io {

using Cell = std::variant<double, std::string>;

// The cell of a number that does not exist (a repose angle without a flank): "n/a" in text, CSV and
// Markdown, null in JSON.
inline const std::string not_available = "n/a";

struct Table {
    std::string title;
    std::vector<std::pair<std::string, std::string>> metadata;  // key, value
    std::vector<std::string> columns;                            // snake_case names carrying their unit
    std::vector<std::string> headings;                           // the columns in words with units, for people (empty: derived)
    std::vector<std::vector<Cell>> rows;
    std::vector<std::string> notes;                              // warnings and remarks shown below
};

enum class Format { text, csv, markdown, json };
Format parse_format(const std::string& text, const std::string& field);

// Text and Markdown show 6 significant digits; CSV and JSON the shortest exact form.
std::string render(const Table& table, Format format);

}  // namespace demscale::io
