#include <catch2/catch.hpp>

#include "io/csv_reader.hpp"
#include "io/table_format.hpp"

using namespace demscale;

TEST_CASE("CSV rendering round-trips through the reader, metadata as # lines", "[io][csv]") {
    io::Table t;
    t.title = "t";
    t.metadata = {{"variant", "mikami1998"}};
    t.columns = {"name", "x_m"};
    t.rows = {{std::string("a,b"), 0.1}, {std::string("say \"hi\""), 1e-300}};
    const auto csv = io::render(t, io::Format::csv);
    const auto d = io::parse_csv(csv, "mem");
    CHECK(d.comments[1] == "variant: mikami1998");
    CHECK(d.header == std::vector<std::string>{"name", "x_m"});
    CHECK(d.rows[0][0] == "a,b");
    CHECK(d.rows[1][0] == "say \"hi\"");
    CHECK(std::stod(d.rows[0][1]) == 0.1);  // shortest exact form reads back bit for bit
    CHECK(std::stod(d.rows[1][1]) == 1e-300);
}

TEST_CASE("Ill-formed CSV is reported with its line", "[io][csv]") {
    CHECK_THROWS_WITH(io::parse_csv("a,b\n1,2\n3\n", "f.csv"), Catch::Matchers::Contains("f.csv:3"));
    CHECK_THROWS_WITH(io::parse_csv("# only comments\n", "f.csv"), Catch::Matchers::Contains("header"));
}

TEST_CASE("Every format renders every row", "[io][format]") {
    io::Table t;
    t.columns = {"radius_mm", "vhat"};
    t.rows = {{1.0, 0.05}, {2.0, 0.05}};
    for (auto f : {io::Format::text, io::Format::markdown, io::Format::json, io::Format::csv}) {
        const auto s = io::render(t, f);
        CHECK(s.find("radius_mm") != std::string::npos);
        CHECK(s.find("0.05") != std::string::npos);
    }
    // Markdown reads as plain text too: padded columns, numbers right-aligned, text left-aligned.
    t.columns.push_back("note");
    t.rows[0].push_back(std::string("γ ok"));
    t.rows[1].push_back(std::string("longer text"));
    const auto md = io::render(t, io::Format::markdown);
    CHECK(md.find("| radius_mm | vhat | note        |\n") != std::string::npos);
    CHECK(md.find("|----------:|-----:|:------------|\n") != std::string::npos);
    CHECK(md.find("|         1 | 0.05 | γ ok        |\n") != std::string::npos);
    CHECK_THROWS(io::parse_format("xml", "--format"));
}
