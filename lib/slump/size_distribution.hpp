// The sizes of a fill's spheres, as ratios to the scene's reference radius R (SlumpScene::radius_m:
// the one radius, or a distribution's mass median): one radius; a sieve table, classes of one
// radius each with their share of the mass; or a lognormal by mass (median R, geometric standard
// deviation σ_g) truncated at two quantiles of the mass. Only the shape is kept here, so
// coarse-graining (R̄ = S_f R) scales every class by S_f and the distribution keeps its shape
// (docs/file-formats.md, "Size distributions").
#pragma once

#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace demscale::slump {

inline constexpr std::size_t max_size_classes = 32;

struct SizeDistribution {
    std::vector<double> class_ratios;    // sieve: each class's radius / R, ascending; empty otherwise
    std::vector<double> mass_fractions;  // sieve: each class's share of the fill's mass, summing to 1
    double geometric_sd = 1;             // lognormal: σ_g > 1; 1: not a lognormal
    double lower_quantile = 0.05, upper_quantile = 0.95;  // lognormal: where the mass distribution is cut

    bool lognormal() const { return geometric_sd > 1; }
    bool sieve() const { return class_ratios.size() > 1; }
    // One radius: every draw is R, and no random number is used.
    bool monodisperse() const { return !lognormal() && !sieve(); }
    // The smallest and largest radius a draw can give, / R.
    double smallest_ratio() const;
    double largest_ratio() const;
};

// One sphere's radius / R, drawn by number so that the drawn spheres' mass follows the
// distribution: a class with mass fraction f_c has number weight f_c / x_c³; a lognormal by mass
// with median 1 and ln σ_g = s is by number a lognormal with median exp(−3 s²) and the same s
// (Hatch & Choate 1929), cut at the same radii. 1 without drawing for one radius.
double draw_radius_ratio(const SizeDistribution& d, std::mt19937_64& rng);

// The mean of (r/R)³ over spheres drawn so: the mean sphere's volume over that of radius R.
double mean_volume_ratio(const SizeDistribution& d);

// The share of the mass in spheres of radius ≤ x R (the distribution's mass CDF, its cut applied).
double mass_fraction_below(const SizeDistribution& d, double x);

// The bins a cut to mass keeps the shares of (slump/pour.hpp): the sieve's classes, 8 bins of
// equal mass for a lognormal, one bin for one radius. Each bin's share of the mass, and the bin of
// a sphere of radius x R.
inline constexpr std::size_t lognormal_bins = 8;
std::vector<double> bin_mass_shares(const SizeDistribution& d);
std::size_t size_bin(const SizeDistribution& d, double x);

// "lognormal by mass, sigma_g = 1.3, cut at mass quantiles 0.05 and 0.95 (0.65 R to 1.54 R)",
// "sieve: 3 classes, 0.7 R (25 %), 1 R (50 %), 1.4 R (25 %)" or "one radius".
std::string describe(const SizeDistribution& d);

}  // namespace demscale::slump
