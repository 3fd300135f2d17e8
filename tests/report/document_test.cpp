// The report document's renderings: base64 against RFC 4648's test vectors, HTML escaping and
// embedding, Markdown links relative to the report.
#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <fstream>

#include "report/caveats.hpp"
#include "report/document.hpp"
#include "report/table_layout.hpp"

using namespace demscale::report;
namespace io = demscale::io;
namespace report = demscale::report;
namespace fs = std::filesystem;

TEST_CASE("base64 matches RFC 4648 section 10", "[report][document]") {
    CHECK(base64("") == "");
    CHECK(base64("f") == "Zg==");
    CHECK(base64("fo") == "Zm8=");
    CHECK(base64("foo") == "Zm9v");
    CHECK(base64("foob") == "Zm9vYg==");
    CHECK(base64("fooba") == "Zm9vYmE=");
    CHECK(base64("foobar") == "Zm9vYmFy");
    CHECK(base64(std::string("\xff\x00\x80", 3)) == "/wCA");
}

TEST_CASE("HTML is self-contained and escaped, Markdown links figures relative to itself", "[report][document]") {
    const fs::path dir = fs::temp_directory_path() / "demscale_document_test";
    fs::create_directories(dir / "figures");
    std::ofstream(dir / "figures" / "a.png", std::ios::binary) << "foobar";
    Document d;
    d.title = "T <1>";
    demscale::io::Table t;
    t.title = "x & y";
    t.columns = {"name", "value"};
    t.rows = {{std::string("<b>"), 0.5}};
    d.sections = {{"First part", {Paragraph{"a < b"}, TableBlock{t}, FigureBlock{dir / "figures" / "a.png", "the figure"}}},
                  {"Second", {BulletList{{"one", "two"}}}}};
    const auto html = render_html(d);
    CHECK(html.find("<title>T &lt;1&gt;</title>") != std::string::npos);
    CHECK(html.find("<p>a &lt; b</p>") != std::string::npos);
    CHECK(html.find("<td>&lt;b&gt;</td><td class=\"num\">0.5</td>") != std::string::npos);
    CHECK(html.find("src=\"data:image/png;base64,Zm9vYmFy\"") != std::string::npos);
    CHECK(html.find("href=\"#first-part\"") != std::string::npos);
    CHECK(html.find("<section id=\"first-part\">") != std::string::npos);
    const auto md = render_markdown(d, dir);
    CHECK(md.find("![the figure](figures/a.png)") != std::string::npos);
    CHECK(md.find("## Second\n") != std::string::npos);
    CHECK(md.find("- two\n") != std::string::npos);
    CHECK(md.find("| name") != std::string::npos);
    d.sections[0].blocks.push_back(FigureBlock{dir / "missing.png", "gone"});
    CHECK_THROWS_WITH(render_html(d), Catch::Matchers::Contains("missing.png"));
    fs::remove_all(dir);
}

TEST_CASE("Wide tables are transposed or split so that every cell appears once", "[report][layout]") {
    // Few rows, many columns: transposed, cell (i, j) becomes (j, i).
    io::Table wide;
    wide.title = "wide";
    wide.columns = {"radius_mm"};
    for (int j = 1; j < 30; ++j) wide.columns.push_back("quantity_number_" + std::to_string(j));
    for (double r : {3.84, 2.74, 1.0}) {
        std::vector<io::Cell> row{r};
        for (int j = 1; j < 30; ++j) row.push_back(r * 1000 + j);
        wide.rows.push_back(row);
    }
    REQUIRE(report::estimated_width(wide) > 140);
    const auto t = report::fit_to_width(wide);
    REQUIRE(t.size() == 1);
    CHECK(t[0].columns == std::vector<std::string>{"radius_mm", "3.84", "2.74", "1"});
    REQUIRE(t[0].rows.size() == 29);
    CHECK(std::get<std::string>(t[0].rows[4][0]) == "quantity_number_5");
    CHECK(std::get<double>(t[0].rows[4][2]) == 2745);
    // Repeated first cells cannot head columns: split instead, each part keyed by the first column.
    wide.rows[1][0] = 3.84;
    const auto parts = report::fit_to_width(wide);
    REQUIRE(parts.size() > 1);
    // Here the first two columns tell the rows apart: every part repeats them, every other column
    // appears in exactly one part, with its cells unchanged.
    std::map<std::string, int> seen;
    for (const auto& p : parts) {
        REQUIRE(p.columns.size() > 2);
        CHECK(p.columns[0] == "radius_mm");
        CHECK(p.columns[1] == "quantity_number_1");
        CHECK(report::estimated_width(p) <= 140);
        for (std::size_t c = 2; c < p.columns.size(); ++c) {
            ++seen[p.columns[c]];
            const int j = std::stoi(p.columns[c].substr(16));
            for (std::size_t i = 0; i < p.rows.size(); ++i) CHECK(p.rows[i][c] == wide.rows[i][static_cast<std::size_t>(j)]);
        }
    }
    CHECK(seen.size() == 28);
    for (const auto& [name, n] : seen) CHECK(n == 1);

    CHECK(parts.back().columns.back() == "quantity_number_29");
    // A narrow table is left alone; numbers show 4 significant digits.
    io::Table narrow;
    narrow.columns = {"a", "b"};
    narrow.rows = {{1.0, 0.000192733}};
    CHECK(report::fit_to_width(narrow).size() == 1);
    CHECK(report::document_cell(io::Cell(0.000192733)) == "0.0001927");
    CHECK(report::document_cell(io::Cell(2195.17)) == "2195");
}

TEST_CASE("Tables for people: headings in words with units, empty columns left out, CSV keeps the identifiers",
          "[report][layout]") {
    CHECK(report::heading_of("fill_mass_g") == "fill mass (g)");
    CHECK(report::heading_of("slump_diff_pct_of_height") == "slump difference (% of fill height)");
    CHECK(report::heading_of("gamma_n_per_m") == "gamma (N/m)");
    CHECK(report::heading_of("sf") == "S_f");
    CHECK(report::heading_of("fhat_mikami1998") == "F̂ mikami1998");
    CHECK(report::heading_of("time_to_rest_s") == "time to rest (s)");
    io::Table t;
    t.title = "t";
    t.columns = {"sf", "repose_deg", "fill_mass_g"};
    t.rows = {{1.0, io::Cell(io::not_available), 12.5}, {1.4, std::string(), 12.4}};
    t.notes = {"fill_mass_g: the fill's solid mass", "sf: scale factor"};
    const auto p = report::for_people(t);
    CHECK(p.columns == std::vector<std::string>{"S_f", "fill mass (g)"});  // the repose column holds nothing
    REQUIRE(p.rows.size() == 2);
    CHECK(std::get<double>(p.rows[1][1]) == 12.4);
    CHECK(p.notes[0] == "fill mass (g): the fill's solid mass");
    t.headings = {"S_f", "angle", "mass of the fill, g"};
    CHECK(report::for_people(t).columns == std::vector<std::string>{"S_f", "mass of the fill, g"});
    CHECK(io::render(t, io::Format::csv).find("sf,repose_deg,fill_mass_g") != std::string::npos);
}

TEST_CASE("Caveats are grouped by kind, listing whom each affects", "[report][layout]") {
    const auto lines = report::grouped_caveats({{"fine", "top opening 4.3 diameters wide (< 5)"},
                                                {"S_f = 1.4, k = 1", "top opening 3.1 diameters wide (< 5)"},
                                                {"S_f = 1.4, k = 1", "runs not at rest"},
                                                {"S_f = 1.4, k = 3", "top opening 3.1 diameters wide (< 5)"},
                                                {"S_f = 1.4, k = 3", "runs not at rest"}});
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] == "top opening N diameters wide (< 5): N = 4.3 (fine), 3.1 (S_f = 1.4, k = 1), 3.1 (S_f = 1.4, k = 3)");
    CHECK(lines[1] == "runs not at rest: S_f = 1.4, k = 1; S_f = 1.4, k = 3");
}
