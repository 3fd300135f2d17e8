// Wide tables laid out for a page (1 400 px screen, A4 print): a table too wide to read is
// transposed when it has few rows, else split into parts that each repeat the first (key) column.
// Widths are estimated in characters of the rendered cells.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/table_format.hpp"

namespace demscale::report {

// A number as a report shows it: 4 significant digits (tables written as CSV keep every digit).
std::string document_cell(const io::Cell& c);

// A CSV identifier in words with its unit: "fill_mass_g" → "fill mass (g)", "slump_diff_pct_of_height"
// → "slump diff (% of height)", "sf" → "S_f", "fhat_mikami1998" → "F̂ mikami1998".
std::string heading_of(const std::string& column);

// The table as a person reads it: columns headed by its headings (or heading_of each identifier),
// columns with no value in any row (empty or n/a) left out, and notes that open with an identifier
// ("fill_mass_ratio: …") opened with its heading instead. CSV and JSON keep the identifiers.
io::Table for_people(io::Table t);

// The estimated width of a table in characters: per column the widest cell or (wrapped) header.
std::size_t estimated_width(const io::Table& t);

// The table itself when it fits max_chars; else its transpose (rows become columns, headed by
// each row's first cell) when that fits; else parts of consecutive columns, each starting with the
// key columns (the fewest leading columns, at most three, that tell the rows apart). Metadata
// stays with the first part, notes with the last.
std::vector<io::Table> fit_to_width(const io::Table& t, std::size_t max_chars = 140);

}  // namespace demscale::report
