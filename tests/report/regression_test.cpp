#include <catch2/catch.hpp>

#include "io/csv_reader.hpp"
#include "report/regression.hpp"

using namespace demscale;

namespace {
const std::string reference = "# meta\nvariant,hhat,sigma_pa\nmikami1998,0,131.2\nmikami1998,0.1,50\n";
}

TEST_CASE("Regression comparison passes within tolerance and fails outside it", "[report][regress]") {
    const auto ref = io::parse_csv(reference, "ref");
    report::Tolerance tol{1e-12, 1e-9};
    CHECK(report::compare_csv(ref, ref, tol, {}).passed());
    // 1e-10 relative change: within 1e-9.
    auto near = io::parse_csv("variant,hhat,sigma_pa\nmikami1998,0,131.2000000131\nmikami1998,0.1,50\n", "got");
    CHECK(report::compare_csv(ref, near, tol, {}).passed());
    // 1e-6 relative change: caught, with the row's key and the column.
    auto drift = io::parse_csv("variant,hhat,sigma_pa\nmikami1998,0,131.2\nmikami1998,0.1,50.00005\n", "got");
    const auto cmp = report::compare_csv(ref, drift, tol, {"variant", "hhat"});
    REQUIRE_FALSE(cmp.passed());
    REQUIRE(cmp.failures.size() == 1);
    CHECK(cmp.failures[0].column == "sigma_pa");
    CHECK(cmp.failures[0].key == "variant=mikami1998 hhat=0.1");
    CHECK(cmp.failures[0].line == 4);
    CHECK(cmp.failures[0].relative == Approx(1e-6).epsilon(1e-3));
    const auto text = report::describe(cmp, "fig4.csv", tol);
    CHECK(text.find("FAIL fig4.csv") != std::string::npos);
    CHECK(text.find("sigma_pa") != std::string::npos);
}

TEST_CASE("Regression comparison reports structural changes", "[report][regress]") {
    const auto ref = io::parse_csv(reference, "ref");
    report::Tolerance tol;
    auto fewer = io::parse_csv("variant,hhat,sigma_pa\nmikami1998,0,131.2\n", "got");
    CHECK(report::compare_csv(ref, fewer, tol, {}).problem.find("row count") != std::string::npos);
    auto renamed = io::parse_csv("variant,hhat,stress_pa\nmikami1998,0,131.2\nmikami1998,0.1,50\n", "got");
    CHECK(report::compare_csv(ref, renamed, tol, {}).problem.find("stress_pa") != std::string::npos);
    auto text = io::parse_csv("variant,hhat,sigma_pa\nyun-park-2017,0,131.2\nmikami1998,0.1,50\n", "got");
    CHECK_FALSE(report::compare_csv(ref, text, tol, {}).passed());
}

TEST_CASE("Regression names changed inputs before values, and summarises each column", "[report][regress]") {
    const std::string body = "variant,hhat,sigma_pa\nmikami1998,0,131.2\nmikami1998,0.1,50\n";
    const auto ref = io::parse_csv("# demscale: 0.1.0\n# inputs: a.toml\n# exponents: 1, 3\n" + body, "ref");
    report::Tolerance tol;
    // Only the tool version and the file name differ: reported, not failed.
    const auto renamed = io::parse_csv("# demscale: 0.2.0\n# inputs: b.toml\n# exponents: 1, 3\n" + body, "got");
    const auto same = report::compare_csv(ref, renamed, tol, {});
    CHECK(same.passed());
    REQUIRE(same.changed_inputs.size() == 2);
    CHECK(same.changed_inputs[0].informational);
    // A changed exponent fails even where the values happen to agree, and is named first.
    const auto other_k = io::parse_csv("# demscale: 0.2.0\n# inputs: a.toml\n# exponents: 1, 2.5\n" + body, "got");
    const auto cmp = report::compare_csv(ref, other_k, tol, {});
    CHECK_FALSE(cmp.passed());
    REQUIRE_FALSE(cmp.changed_inputs.empty());
    CHECK(cmp.changed_inputs[0].key == "exponents");
    CHECK(cmp.changed_inputs[0].reference == "1, 3");
    CHECK(cmp.changed_inputs[0].computed == "1, 2.5");
    const auto text = report::describe(cmp, "fig4.csv", tol);
    CHECK(text.find("exponents: 1, 3 -> 1, 2.5") < text.find("demscale: 0.1.0 -> 0.2.0"));
    // A key only one side has counts as changed.
    const auto added = io::parse_csv("# demscale: 0.1.0\n# inputs: a.toml\n# exponents: 1, 3\n# radii_mm: 1\n" + body, "got");
    CHECK(report::compare_csv(ref, added, tol, {}).changed_inputs.at(0).reference == "(absent)");
    // Column summary: two values of sigma_pa off, the larger relative difference (10 %) is the one reported.
    const auto drift = io::parse_csv("# demscale: 0.1.0\n# inputs: a.toml\n# exponents: 1, 3\n"
                                     "variant,hhat,sigma_pa\nmikami1998,0,132.2\nmikami1998,0.1,55\n", "got");
    const auto d = report::compare_csv(ref, drift, tol, {"hhat"});
    REQUIRE(d.columns.size() == 1);
    CHECK(d.columns[0].column == "sigma_pa");
    CHECK(d.columns[0].outside == 2);
    CHECK(d.columns[0].largest.relative == Approx(0.1));
    CHECK(d.columns[0].largest.key == "hhat=0.1");
}
