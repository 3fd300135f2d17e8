#include "report/document.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/input_error.hpp"
#include "report/table_layout.hpp"

namespace demscale::report {

namespace fs = std::filesystem;

namespace {

template <class... F>
struct Visitor : F... {
    using F::operator()...;
};
template <class... F>
Visitor(F...) -> Visitor<F...>;

std::string escape_html(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

std::string anchor(const std::string& title) {
    std::string a;
    for (char c : title)
        if (std::isalnum(static_cast<unsigned char>(c))) a += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (!a.empty() && a.back() != '-') a += '-';
    return a;
}

std::string cell_text(const io::Cell& c) { return document_cell(c); }

// A table's numbers as the report shows them (Markdown renders strings as they are).
io::Table with_document_numbers(io::Table t) {
    for (auto& row : t.rows)
        for (auto& c : row) c = document_cell(c);
    return t;
}

std::string read_binary(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read figure " + file.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void html_table_part(std::ostringstream& h, const io::Table& t) {
    h << "<figure class=\"table\"><figcaption>" << escape_html(t.title) << "</figcaption>\n";
    if (!t.metadata.empty()) {
        h << "<ul class=\"meta\">";
        for (const auto& [k, v] : t.metadata) h << "<li><b>" << escape_html(k) << "</b>: " << escape_html(v) << "</li>";
        h << "</ul>\n";
    }
    h << "<div class=\"scroll\"><table>\n<thead><tr>";
    for (const auto& c : t.columns) h << "<th>" << escape_html(c) << "</th>";
    h << "</tr></thead>\n<tbody>\n";
    for (const auto& row : t.rows) {
        h << "<tr>";
        for (const auto& c : row)
            h << (std::holds_alternative<double>(c) ? "<td class=\"num\">" : cell_text(c).size() > 40 ? "<td class=\"long\">" : "<td>")
              << escape_html(cell_text(c)) << "</td>";
        h << "</tr>\n";
    }
    h << "</tbody></table></div>\n";
    for (const auto& n : t.notes) h << "<p class=\"note\">" << escape_html(n) << "</p>\n";
    h << "</figure>\n";
}

void html_table(std::ostringstream& h, const io::Table& t) {
    for (const auto& part : fit_to_width(for_people(t))) html_table_part(h, part);
}

const char* style = R"(body{font-family:'DejaVu Sans',Helvetica,Arial,sans-serif;max-width:1180px;margin:2em auto;padding:0 1.5em;color:#1b1b1b;line-height:1.45}
h1{border-bottom:2px solid #2166ac;padding-bottom:.3em}h2{margin-top:2em;border-bottom:1px solid #ccc;padding-bottom:.2em}
nav ol{columns:2}table{border-collapse:collapse;font-size:.86em}th,td{border:1px solid #d0d0d0;padding:.25em .55em;vertical-align:top}
th{background:#eef3f8;text-align:left;overflow-wrap:break-word;max-width:9em}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
tbody tr:nth-child(even){background:#fafafa}figure{margin:1.2em 0}figcaption{font-weight:bold;margin-bottom:.4em}
figure.plot figcaption{font-weight:normal;font-style:italic;margin-top:.3em}.scroll{overflow-x:auto}
ul.meta{font-size:.85em;color:#444;margin:.2em 0 .5em}p.note{font-size:.85em;color:#555;margin:.2em 0}
img{max-width:100%;border:1px solid #e0e0e0}td.long{min-width:24em}
figure.half{display:inline-block;width:49%;margin:.5em 0;vertical-align:top}figure.half figcaption{font-size:.85em}
@media print{body{max-width:none;margin:0;padding:0}.scroll{overflow:visible}table{font-size:7pt}
th,td{padding:.1em .25em}th{overflow-wrap:anywhere}td.num{white-space:normal}td.long{min-width:0}figure,tr{break-inside:avoid}})";

}  // namespace

std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        for (int s = 18; s >= 0; s -= 6) out += alphabet[(n >> s) & 63];
    }
    if (i < bytes.size()) {
        const bool two = i + 1 < bytes.size();
        const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
        out += alphabet[(n >> 18) & 63];
        out += alphabet[(n >> 12) & 63];
        out += two ? alphabet[(n >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string render_markdown(const Document& d, const fs::path& markdown_dir) {
    std::ostringstream m;
    m << "# " << d.title << "\n\n";
    for (const auto& s : d.sections) m << "- [" << s.title << "](#" << anchor(s.title) << ")\n";
    for (const auto& s : d.sections) {
        m << "\n## " << s.title << "\n";
        for (const auto& b : s.blocks)
            std::visit(Visitor{[&](const Paragraph& p) { m << "\n" << p.text << "\n"; },
                               [&](const BulletList& l) {
                                   m << "\n";
                                   for (const auto& i : l.items) m << "- " << i << "\n";
                               },
                               [&](const TableBlock& t) {
                                   for (const auto& part : fit_to_width(for_people(t.table)))
                                       m << "\n" << io::render(with_document_numbers(part), io::Format::markdown);
                               },
                               [&](const FigureBlock& f) {
                                   m << "\n![" << f.caption << "](" << fs::relative(f.png, markdown_dir).generic_string()
                                     << ")\n\n*" << f.caption << "*\n";
                               }},
                       b);
    }
    return m.str();
}

std::string render_html(const Document& d) {
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" << escape_html(d.title)
      << "</title>\n<style>" << style << "</style></head>\n<body>\n<h1>" << escape_html(d.title) << "</h1>\n<nav><ol>";
    for (const auto& s : d.sections) h << "<li><a href=\"#" << anchor(s.title) << "\">" << escape_html(s.title) << "</a></li>";
    h << "</ol></nav>\n";
    for (const auto& s : d.sections) {
        h << "<section id=\"" << anchor(s.title) << "\">\n<h2>" << escape_html(s.title) << "</h2>\n";
        for (const auto& b : s.blocks)
            std::visit(Visitor{[&](const Paragraph& p) { h << "<p>" << escape_html(p.text) << "</p>\n"; },
                               [&](const BulletList& l) {
                                   h << "<ul>";
                                   for (const auto& i : l.items) h << "<li>" << escape_html(i) << "</li>";
                                   h << "</ul>\n";
                               },
                               [&](const TableBlock& t) { html_table(h, t.table); },
                               [&](const FigureBlock& f) {
                                   h << "<figure class=\"plot" << (f.half_width ? " half" : "") << "\"><img alt=\"" << escape_html(f.caption)
                                     << "\" src=\"data:image/png;base64," << base64(read_binary(f.png)) << "\">\n<figcaption>"
                                     << escape_html(f.caption) << "</figcaption></figure>\n";
                               }},
                       b);
        h << "</section>\n";
    }
    h << "</body></html>\n";
    return h.str();
}

}  // namespace demscale::report
