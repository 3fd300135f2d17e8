#include "slump/size_distribution.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>

#include "core/input_error.hpp"

namespace demscale::slump {

namespace {

double log_sd(const SizeDistribution& d) { return std::log(d.geometric_sd); }

// The standard-normal cut of the number distribution, ln x = −3 s² + s y with y in [α, β].
struct NumberCut {
    double alpha, beta;
};
NumberCut number_cut(const SizeDistribution& d) {
    const double s = log_sd(d);
    return {gsl_cdf_ugaussian_Pinv(d.lower_quantile) + 3 * s, gsl_cdf_ugaussian_Pinv(d.upper_quantile) + 3 * s};
}

// Σ f_c / x_c³: a class's share of the spheres is its f_c / x_c³ over this, and the mean (r/R)³
// its inverse.
double inverse_mean_volume(const SizeDistribution& d) {
    double sum = 0;
    for (std::size_t c = 0; c < d.class_ratios.size(); ++c) sum += d.mass_fractions[c] / std::pow(d.class_ratios[c], 3);
    return sum;
}

}  // namespace

double SizeDistribution::smallest_ratio() const {
    if (lognormal()) return std::exp(log_sd(*this) * gsl_cdf_ugaussian_Pinv(lower_quantile));
    return sieve() ? class_ratios.front() : 1.0;
}

double SizeDistribution::largest_ratio() const {
    if (lognormal()) return std::exp(log_sd(*this) * gsl_cdf_ugaussian_Pinv(upper_quantile));
    return sieve() ? class_ratios.back() : 1.0;
}

double draw_radius_ratio(const SizeDistribution& d, std::mt19937_64& rng) {
    if (d.monodisperse()) return 1.0;
    std::uniform_real_distribution<double> unit(0, 1);
    if (d.sieve()) {  // a class by its share of the spheres
        double u = unit(rng) * inverse_mean_volume(d);
        for (std::size_t c = 0; c + 1 < d.class_ratios.size(); ++c) {
            const double w = d.mass_fractions[c] / std::pow(d.class_ratios[c], 3);
            if (u < w) return d.class_ratios[c];
            u -= w;
        }
        return d.class_ratios.back();
    }
    const auto [alpha, beta] = number_cut(d);
    const double lo = gsl_cdf_ugaussian_P(alpha), hi = gsl_cdf_ugaussian_P(beta), s = log_sd(d);
    const double y = gsl_cdf_ugaussian_Pinv(lo + (hi - lo) * unit(rng));
    return std::clamp(std::exp(-3 * s * s + s * y), d.smallest_ratio(), d.largest_ratio());  // the cut, against rounding
}

double mean_volume_ratio(const SizeDistribution& d) {
    if (d.monodisperse()) return 1.0;
    if (d.sieve()) return 1 / inverse_mean_volume(d);
    // E[x³] of the cut number lognormal: exp(−9s²/2) (Φ(β − 3s) − Φ(α − 3s)) / (Φ(β) − Φ(α)), and
    // β − 3s, α − 3s are the mass quantiles' own z.
    const auto [alpha, beta] = number_cut(d);
    const double s = log_sd(d);
    return std::exp(-4.5 * s * s) * (d.upper_quantile - d.lower_quantile) / (gsl_cdf_ugaussian_P(beta) - gsl_cdf_ugaussian_P(alpha));
}

double mass_fraction_below(const SizeDistribution& d, double x) {
    if (d.sieve()) {
        double f = 0;
        for (std::size_t c = 0; c < d.class_ratios.size(); ++c)
            if (d.class_ratios[c] <= x) f += d.mass_fractions[c];
        return std::min(f, 1.0);
    }
    if (!d.lognormal()) return x >= 1 ? 1.0 : 0.0;
    const double q = gsl_cdf_ugaussian_P(std::log(x) / log_sd(d));
    return std::clamp((q - d.lower_quantile) / (d.upper_quantile - d.lower_quantile), 0.0, 1.0);
}

std::vector<double> bin_mass_shares(const SizeDistribution& d) {
    if (d.sieve()) return d.mass_fractions;
    if (d.lognormal()) return std::vector<double>(lognormal_bins, 1.0 / lognormal_bins);
    return {1.0};
}

std::size_t size_bin(const SizeDistribution& d, double x) {
    if (d.sieve())  // the nearest class (a sphere's radius is its class's, up to rounding)
        return static_cast<std::size_t>(std::min_element(d.class_ratios.begin(), d.class_ratios.end(),
                                                         [x](double a, double b) { return std::abs(a - x) < std::abs(b - x); }) -
                                        d.class_ratios.begin());
    if (d.lognormal()) return std::min(lognormal_bins - 1, static_cast<std::size_t>(lognormal_bins * mass_fraction_below(d, x)));
    return 0;
}

std::string describe(const SizeDistribution& d) {
    if (d.lognormal())
        return "lognormal by mass, sigma_g = " + format_short(d.geometric_sd, 4) + ", cut at mass quantiles " + format_short(d.lower_quantile, 3) +
               " and " + format_short(d.upper_quantile, 3) + " (" + format_short(d.smallest_ratio(), 3) + " R to " +
               format_short(d.largest_ratio(), 3) + " R)";
    if (!d.sieve()) return "one radius";
    std::string text = "sieve: " + std::to_string(d.class_ratios.size()) + " classes";
    for (std::size_t c = 0; c < d.class_ratios.size(); ++c)
        text += ", " + format_short(d.class_ratios[c], 3) + " R (" + format_short(100 * d.mass_fractions[c], 3) + " %)";
    return text;
}

}  // namespace demscale::slump
