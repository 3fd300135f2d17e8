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
