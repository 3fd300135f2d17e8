// The bridge-model interface and the tabulated exact model.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

#include "bridge/bridge_model.hpp"
#include "bridge/bridge_table.hpp"
#include "bridge/young_laplace.hpp"
#include "core/input_error.hpp"
#include "io/bridge_table_file.hpp"

using namespace demscale;
using namespace demscale::bridge;

namespace {
const std::string table_path = DEMSCALE_SOURCE_DIR "/data/bridge_table.csv";
}

TEST_CASE("Every bridge model: zero beyond its rupture, contact value for overlap, finite inside", "[bridge][models]") {
    const auto table = io::read_bridge_table(table_path);
    for (auto name : bridge_model_names()) {
        if (name == "exact") continue;  // covered by its own tests
        const auto m = make_bridge_model(name, &table);
        for (double vhat : {1e-5, 1e-3, 0.05544, 0.3}) {
            for (double deg : {0.0, 30.0}) {
                const ContactAngle theta{Degrees{deg}};
                const double hc = m->hhat_rupture(vhat, theta);
                INFO(name << " vhat=" << vhat << " theta=" << deg);
                REQUIRE(std::isfinite(hc));
                CHECK(m->fhat(vhat, theta, hc * 1.0001) == 0.0);
                CHECK(m->fhat(vhat, theta, -0.01) == m->fhat(vhat, theta, 0.0));
                for (double x : {0.0, 0.3, 0.7, 0.999}) {
                    const double f = m->fhat(vhat, theta, x * hc);
                    CHECK(std::isfinite(f));
                    CHECK(f >= 0.0);
                }
            }
        }
    }
    CHECK_THROWS_WITH(make_bridge_model("wilett"), Catch::Matchers::Contains("did you mean willett"));
    CHECK_THROWS_WITH(make_bridge_model("table"), Catch::Matchers::Contains("--table"));  // no table given
}

TEST_CASE("Tabulated model: error against the exact solver at random off-grid points below 0.5 %", "[bridge][table]") {
    // Measured on these 20 points (seed 42): worst 0.18 %, worst rupture-distance error 0.63 %.
    const auto table = io::read_bridge_table(table_path);
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 20; ++i) {
        const double vhat = std::exp(std::log(1e-5) + u(rng) * (std::log(0.3) - std::log(1e-5)));
        const ContactAngle theta{Degrees{40 * u(rng)}};
        const double x = 0.98 * u(rng);
        const YoungLaplaceBridge exact(vhat, theta);
        const auto r = exact.solve(x * exact.hhat_rupture());
        REQUIRE(r.ok());
        INFO("vhat=" << vhat << " theta=" << theta.degrees() << " x=" << x);
        CHECK(std::abs(table.fhat(vhat, theta, x * exact.hhat_rupture()) / r.shape.fhat_neck - 1) < 5e-3);
        CHECK(std::abs(table.hhat_rupture(vhat, theta) / exact.hhat_rupture() - 1) < 1e-2);
    }
}

TEST_CASE("Tabulated model: the file written back from what was read is the same file, byte for byte", "[bridge][table]") {
    std::ifstream in(table_path);
    const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(io::bridge_table_csv(io::read_bridge_table(table_path)) == file);
}

TEST_CASE("Tabulated model: continuous across cells, refuses what it does not cover", "[bridge][table]") {
    const auto table = io::read_bridge_table(table_path);
    const ContactAngle theta{Degrees{10}};  // a theta node: the neighbouring cells meet here
    const auto pair = table.prepare(0.01, theta);
    for (int node = 1; node < table.grid().gap_points - 1; ++node) {
        const double x = 0.5 * (1 - std::cos(M_PI * node / (table.grid().gap_points - 1)));
        const double h = x * pair.hhat_rupture;
        CHECK(pair.fhat(h * (1 - 1e-9)) == Approx(pair.fhat(h * (1 + 1e-9))).epsilon(1e-6));
    }
    CHECK_THROWS_AS(table.fhat(1e-6, theta, 0.0), InputError);
    CHECK_THROWS_AS(table.fhat(0.01, ContactAngle{Degrees{50}}, 0.0), InputError);
    CHECK_THROWS_AS(io::read_bridge_table(DEMSCALE_SOURCE_DIR "/data/table1.toml"), InputError);
}

namespace {
bool flagged(const ModelEvaluation& e, const std::string& code) {
    return std::any_of(e.flags.begin(), e.flags.end(), [&](const ValidityWarning& w) { return w.code == code; });
}
}  // namespace

TEST_CASE("Fitted models flag themselves: range, physical bound, clamping, no shape", "[bridge][models][validity]") {
    const ContactAngle zero{Degrees{0}}, forty{Degrees{40}};
    const auto mikami = make_bridge_model("mikami1998");
    // The cases that printed impossible numbers without a word. The bound F/(2πRγ) ≤ cos θ is the
    // exact bridge's small-volume limit at contact (young_laplace_test: approached from below).
    for (auto [vhat, theta] : {std::pair{1e-308, zero}, {1e-7, forty}}) {
        const auto e = evaluate(*mikami, vhat, theta, 0.0);
        INFO("V^ = " << vhat);
        CHECK(e.fhat > std::cos(theta.radians()));
        CHECK(flagged(e, "outside_fitted_range"));
        CHECK(flagged(e, "above_physical_bound"));
    }
    CHECK(evaluate(*mikami, 0.05544, zero, 0.0).flags.empty());  // Table 1's bridge: inside, below the bound
    CHECK(flagged(evaluate(*make_bridge_model("willett"), 1e-6, zero, 0.0), "above_physical_bound"));
    // The printed variant turns negative before its rupture distance: 0, flagged, and no bridge.
    const auto clamped = evaluate(*make_bridge_model("yun-park-2017"), 1e-3, zero, 0.06);
    CHECK(clamped.fhat == 0);
    CHECK(0.06 < clamped.hhat_rupture);
    CHECK(flagged(clamped, "clamped"));
    CHECK_FALSE(clamped.bridge_exists);
    // No circle meridian: an error naming the inputs, not a force of 0.
    CHECK_THROWS_AS(evaluate(*make_bridge_model("toroidal"), 0.3, ContactAngle{Degrees{70}}, 0.1), InputError);
    // Every model: a bridge exists exactly where the printed force is positive; its range has a source.
    const auto table = io::read_bridge_table(table_path);
    for (auto name : bridge_model_names()) {
        const auto m = make_bridge_model(name, &table);
        CHECK_FALSE(m->fitted_range().source.empty());
        if (name == "exact") continue;
        for (double vhat : {1e-4, 0.01, 0.1})
            for (double x : {0.0, 0.5, 0.95, 1.2}) {
                const double hhat = x * m->hhat_rupture(vhat, zero);
                const auto e = evaluate(*m, vhat, zero, hhat);
                INFO(name << " V^ = " << vhat << ", h^ = " << hhat);
                CHECK(e.bridge_exists == (e.fhat > 0));
            }
    }
}
