// Size distributions: the spheres drawn by number carry the mass fractions of a sieve table and the
// mass distribution of a cut lognormal, within sampling error (by the delta method,
// sampling_error.hpp); the cut's radii and the mean volume against GSL's lognormal and a Monte Carlo mean; one
// radius draws nothing; scenes read the keys and refuse bad ones naming them.
#include <catch2/catch.hpp>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "core/input_error.hpp"
#include "slump/slump_scene.hpp"
#include "sampling_error.hpp"

using namespace demscale;
using namespace demscale::slump;

namespace {

SlumpScene scene_from(const std::string& particles) {
    const auto path = std::filesystem::temp_directory_path() / "demscale_size_distribution_test.toml";
    std::ofstream(path) << "[particles]\n" << particles << "\n";
    return load_slump_scene(path.string());
}

}  // namespace

TEST_CASE("A sieve table drawn by number gives each class its mass fraction within 4 standard errors", "[slump][sizes]") {
    SizeDistribution d;
    d.class_ratios = {0.7, 1.0, 1.4};
    d.mass_fractions = {0.25, 0.5, 0.25};
    std::mt19937_64 rng(7);
    constexpr int n = 200000;
    std::vector<double> mass(3, 0.0);
    double total = 0, cubes = 0;
    for (int i = 0; i < n; ++i) {
        const double x = draw_radius_ratio(d, rng);
        const auto c = static_cast<std::size_t>(std::find(d.class_ratios.begin(), d.class_ratios.end(), x) - d.class_ratios.begin());
        REQUIRE(c < 3);
        mass[c] += x * x * x, total += x * x * x, cubes += x * x * x;
    }
    for (std::size_t c = 0; c < 3; ++c) {
        INFO("class " << c);
        CHECK(std::abs(mass[c] / total - d.mass_fractions[c]) < 4 * class_mass_fraction_error(d.class_ratios, d.mass_fractions, c, n));
    }
    // The mean volume: 1 / Σ f_c / x_c³ by hand, and the sample's mean.
    const double by_hand = 1 / (0.25 / 0.343 + 0.5 + 0.25 / 2.744);
    CHECK(mean_volume_ratio(d) == Approx(by_hand).epsilon(1e-12));
    CHECK(cubes / n == Approx(by_hand).epsilon(0.01));
    CHECK(d.smallest_ratio() == 0.7);
    CHECK(d.largest_ratio() == 1.4);
}

TEST_CASE("A cut lognormal drawn by number follows the mass distribution GSL's lognormal gives", "[slump][sizes]") {
    SizeDistribution d;
    d.geometric_sd = 1.3, d.lower_quantile = 0.05, d.upper_quantile = 0.95;
    const double s = std::log(1.3);
    // The cut at the mass quantiles, by GSL's own lognormal.
    CHECK(d.smallest_ratio() == Approx(gsl_cdf_lognormal_Pinv(0.05, 0, s)).epsilon(1e-12));
    CHECK(d.largest_ratio() == Approx(gsl_cdf_lognormal_Pinv(0.95, 0, s)).epsilon(1e-12));
    std::mt19937_64 rng(11);
    constexpr int n = 200000;
    std::vector<double> x;
    double total = 0;
    for (int i = 0; i < n; ++i) {
        x.push_back(draw_radius_ratio(d, rng));
        total += std::pow(x.back(), 3);
        REQUIRE(x.back() >= d.smallest_ratio());
        REQUIRE(x.back() <= d.largest_ratio());
    }
    CHECK(total / n == Approx(mean_volume_ratio(d)).epsilon(0.005));  // the closed form against the sample
    // The sample's mass below a radius against (P(r) − 0.05) / 0.9 of the uncut lognormal by mass.
    for (double q : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        const double r = gsl_cdf_lognormal_Pinv(q, 0, s), expected = (gsl_cdf_lognormal_P(r, 0, s) - 0.05) / 0.9;
        double below = 0, spread = 0;
        for (double xi : x) below += xi <= r ? std::pow(xi, 3) : 0.0;
        // Its standard error by the delta method, as class_mass_fraction_error with the sample for the weights.
        for (double xi : x) spread += std::pow(std::pow(xi, 3) * ((xi <= r ? 1.0 : 0.0) - expected), 2);
        const double error = std::sqrt(spread / n / n) / (total / n);
        INFO("mass quantile " << q << ": " << below / total << " against " << expected << " +- " << error);
        CHECK(mass_fraction_below(d, r) == Approx(expected).epsilon(1e-9));
        CHECK(std::abs(below / total - expected) < 4 * error);
    }
}

TEST_CASE("One radius draws no random number and gives R", "[slump][sizes]") {
    SizeDistribution d;
    std::mt19937_64 rng(3), untouched(3);
    CHECK(d.monodisperse());
    CHECK(draw_radius_ratio(d, rng) == 1.0);
    CHECK(rng() == untouched());
    CHECK(mean_volume_ratio(d) == 1.0);
}

TEST_CASE("Scenes read a size distribution, R the mass median, and refuse bad keys naming them", "[slump][sizes][input]") {
    const auto sieve = scene_from("distribution = \"sieve\"\nclass_radii_mm = [0.7, 1.0, 1.3]\nmass_fractions = [0.3, 0.3, 0.4]");
    CHECK(sieve.radius_m == Approx(1.0e-3));  // 0.3 below 1 mm, 0.6 up to it: the median class
    CHECK(sieve.sizes.class_ratios[2] == Approx(1.3));
    CHECK(largest_radius(sieve) == Approx(1.3e-3));
    const auto lognormal = scene_from("distribution = \"lognormal\"\nmedian_radius_mm = 0.8\ngeometric_sd = 1.3\nmass_quantiles = [0.1, 0.9]");
    CHECK(lognormal.radius_m == Approx(0.8e-3));
    CHECK(smallest_radius(lognormal) == Approx(0.8e-3 * gsl_cdf_lognormal_Pinv(0.1, 0, std::log(1.3))));
    auto refused = [](const std::string& text, const std::string& key) {
        INFO(text);
        CHECK_THROWS_WITH(scene_from(text), Catch::Contains(key));
        CHECK_THROWS_AS(scene_from(text), InputError);
    };
    refused("distribution = \"sieve\"\nclass_radii_mm = [1.0, 0.7]\nmass_fractions = [0.5, 0.5]", "particles.class_radii_mm");
    refused("distribution = \"sieve\"\nclass_radii_mm = [0.7, 1.0]\nmass_fractions = [0.5, 0.6]", "particles.mass_fractions");
    refused("distribution = \"sieve\"\nclass_radii_mm = [0.7, 1.0]\nmass_fractions = [1.0]", "particles.mass_fractions");
    refused("distribution = \"sieve\"\nradius_mm = 1\nclass_radii_mm = [0.7, 1.0]\nmass_fractions = [0.5, 0.5]", "particles.radius_mm");
    refused("distribution = \"lognormal\"\ngeometric_sd = 1.3", "particles.median_radius_mm");
    refused("distribution = \"lognormal\"\nmedian_radius_mm = 1\ngeometric_sd = 0.9", "particles.geometric_sd");
    refused("distribution = \"lognormal\"\nmedian_radius_mm = 1\nmass_quantiles = [0.5, 0.9]", "particles.mass_quantiles");
    refused("distribution = \"lognormal\"\nmedian_radius_mm = 4\ngeometric_sd = 2", "particles.geometric_sd");  // does not pass the opening
    refused("distribution = \"bimodal\"", "particles.distribution");
    refused("radius_mm = 1\ngeometric_sd = 1.3", "particles.geometric_sd");
    refused("distribution = \"lognormal\"\nmedian_radius_mm = 1\nfill = \"lattice\"", "particles.fill");
}
