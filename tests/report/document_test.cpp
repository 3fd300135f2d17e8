// The report document's renderings: base64 against RFC 4648's test vectors, HTML escaping and
// embedding, Markdown links relative to the report.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "report/document.hpp"

using namespace demscale::report;
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
