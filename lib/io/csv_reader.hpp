// Reads the CSV files demscale writes: `#` metadata lines, one header row, data rows.
// Quoted fields ("a,b", "say ""x""") are understood.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace demscale::io {

struct CsvData {
    std::vector<std::string> comments;             // `#` lines without the leading "# "
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::vector<int> row_lines;                    // 1-based file line of each row
};

// Throws InputError naming source and line for an empty file, a missing header or a row whose
// field count differs from the header's.
CsvData parse_csv(const std::string& text, const std::string& source);
CsvData read_csv_file(const std::string& path);

// A field as a finite number, the whole field read but for spaces around it ("1e-3", " 2" yes;
// "", "1 mm", "nan", "inf" no).
std::optional<double> finite_number(std::string_view field);

}  // namespace demscale::io
