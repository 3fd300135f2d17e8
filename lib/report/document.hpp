// A report as data — sections of paragraphs, lists, tables and figures — and its two renderings:
// Markdown (figures linked beside it) and one self-contained HTML file (figures embedded as PNG
// data, inline style, nothing fetched from a network).
#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "io/table_format.hpp"

namespace demscale::report {

struct Paragraph {
    std::string text;
};
struct BulletList {
    std::vector<std::string> items;
};
struct TableBlock {
    io::Table table;
};
struct FigureBlock {
    std::filesystem::path png;  // an existing PNG file
    std::string caption;
    bool half_width = false;    // HTML: two such figures side by side (a gallery of small multiples)
};
using Block = std::variant<Paragraph, BulletList, TableBlock, FigureBlock>;

struct Section {
    std::string title;
    std::vector<Block> blocks;
};

struct Document {
    std::string title;
    std::vector<Section> sections;
};

// Figures are linked relative to markdown_dir (where the .md file will live).
std::string render_markdown(const Document& d, const std::filesystem::path& markdown_dir);

// Throws std::runtime_error naming a figure that cannot be read.
std::string render_html(const Document& d);

// RFC 4648 base64, for data: URIs.
std::string base64(const std::string& bytes);

}  // namespace demscale::report
