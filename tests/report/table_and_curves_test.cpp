// The derived similarity table and the Fig. 3-4 curves, checked against independent values:
// the density fit by hand, the collapse by the S_f^(k-1) law, and the CSV interface by name.
#include <catch2/catch.hpp>
#include <cmath>

#include "io/csv_reader.hpp"
#include "io/table_config.hpp"
#include "report/curves.hpp"
#include "report/similarity_table.hpp"
#include "report/table1_particles.hpp"

using namespace demscale;

namespace {
io::TableConfig shipped() { return io::load_table_config(DEMSCALE_SOURCE_DIR "/data/table1.toml"); }
}  // namespace

TEST_CASE("Density implied by Table 1's masses", "[report][density]") {
    // docs/model.md §1 [V]: least squares 2.195 g/cm^3; every rounded mass consistent for rho in [2.175, 2.214].
    const auto c = shipped();
    const auto fit = report::fit_density(c.radii_m, c.tabulated_masses_kg, c.mass_resolution_kg);
    CHECK(fit.least_squares_kg_per_m3 == Approx(2195).margin(1));
    REQUIRE(fit.consistent_min_kg_per_m3.has_value());
    CHECK(*fit.consistent_min_kg_per_m3 == Approx(2175).margin(1));
    CHECK(*fit.consistent_max_kg_per_m3 == Approx(2214).margin(1));
    // Independent check of the interval: at both ends every printed mass is reproduced within half a rounding step.
    for (std::size_t i = 0; i < c.radii_m.size(); ++i) {
        const double v = 4.0 / 3.0 * M_PI * std::pow(c.radii_m[i], 3);
        CHECK(std::abs(*fit.consistent_min_kg_per_m3 * v - c.tabulated_masses_kg[i]) <= 0.5e-5 + 1e-15);
        CHECK(std::abs(*fit.consistent_max_kg_per_m3 * v - c.tabulated_masses_kg[i]) <= 0.5e-5 + 1e-15);
    }
}

TEST_CASE("Table CSV has the stable interface columns", "[report][table]") {
    const auto c = shipped();
    const auto t = report::similarity_table(c, {1.0, 3.0, 1.5});
    const auto d = io::parse_csv(io::render(t, io::Format::csv), "table");
    for (const char* col : {"radius_mm", "sf", "mass_g", "v_mm3", "vhat", "a", "b", "c", "fc_contact_n", "hhat_rupture",
                            "gamma_n_per_m_k1", "fc_contact_n_k1", "sigma_contact_pa_k1", "sigma_contact_pa_k3",
                            "gamma_n_per_m_k1p5", "validity"}) {
        INFO(col);
        CHECK(std::find(d.header.begin(), d.header.end(), col) != d.header.end());
    }
    CHECK(d.rows.size() == 5);
    bool has_variant = false;
    for (const auto& line : d.comments) has_variant |= line.find("bridge_variant: mikami1998") != std::string::npos;
    CHECK(has_variant);
}

TEST_CASE("Fig. 3 collapses, Fig. 4 collapses for k = 1 and spreads as S_f^2 for k = 3", "[report][curves]") {
    const auto c = shipped();
    for (const auto& x : report::measure_collapse(report::compute_curves(c, report::Figure::force, {}), report::Figure::force))
        CHECK(x.max_relative_spread < 1e-12);
    const auto stress = report::measure_collapse(report::compute_curves(c, report::Figure::stress, {1.0, 3.0}),
                                                 report::Figure::stress);
    REQUIRE(stress.size() == 4);  // 2 variants x 2 exponents
    for (const auto& x : stress) {
        INFO("k = " << x.exponent);
        if (x.exponent == 1.0) CHECK(x.max_relative_spread < 1e-12);
        // sigma proportional to S_f^2: spread (max - min)/max = 1 - (1/3.84)^2 = 0.932183
        if (x.exponent == 3.0) CHECK(x.max_relative_spread == Approx(1 - 1 / (3.84 * 3.84)).epsilon(1e-9));
    }
}

TEST_CASE("With the printed rounded masses V^ varies and the Fig. 3 curves no longer collapse", "[report][curves]") {
    auto c = shipped();
    c.mass_source = io::MassSource::table;
    const auto p = report::table1_particles(c);
    CHECK(p.rows[3].vhat == Approx(0.06591).epsilon(1e-3));  // R = 1.40 mm, docs/model.md §1
    for (const auto& x : report::measure_collapse(report::compute_curves(c, report::Figure::force, {}), report::Figure::force))
        CHECK(x.max_relative_spread > 0.01);
}

TEST_CASE("Curves: zero beyond rupture, never NaN, both variants present", "[report][curves]") {
    const auto c = shipped();
    const auto pts = report::compute_curves(c, report::Figure::stress, {1.0, 3.0});
    std::size_t printed = 0;
    for (const auto& q : pts) {
        REQUIRE(std::isfinite(q.sigma_pa));
        REQUIRE(std::isfinite(q.f_over_pi_r_gamma));
        if (!q.bridge_exists) REQUIRE(q.force_n == 0.0);
        printed += q.variant == bridge::MikamiVariant::yun_park_2017;
    }
    CHECK(printed == pts.size() / 2);
}
