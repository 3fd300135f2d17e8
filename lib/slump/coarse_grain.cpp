#include "slump/coarse_grain.hpp"

#include <algorithm>
#include <cmath>

#include "core/input_error.hpp"
#include "dem/law_parts.hpp"
#include "similarity/exponent_similarity.hpp"

namespace demscale::slump {

SlumpScene coarse_grained(const SlumpScene& fine, const CoarseGraining& c) {
    require_positive(c.sf, "--sf");
    require_in_open_interval(c.exponent, -20, 20, "--exponent");
    SlumpScene s = fine;
    s.radius_m = fine.radius_m * c.sf;                                                          // Eq. 9: R̄ = S_f R
    s.skin_m = fine.skin_m * c.sf;
    // The law parts' parameters by the rule their tables declare: γ̄ = γ·S_f^k (Eq. 12, any k);
    // a scalable one named in --scale by what its dimension demands under the basis k implies.
    // gravity and the lift speed are the scene's own, scaled the same way when named.
    std::vector<std::string_view> known = {"gravity", "velocity"};
    for (const auto& part : dem::law_parts())
        for (const auto& p : part.parameters) {
            if (p.replacement == dem::Replacement::surface_tension) p.set(s, p.get(fine) * std::pow(c.sf, c.exponent));
            if (p.replacement != dem::Replacement::scalable) continue;
            known.push_back(p.scale_name);
            if (std::find(c.scaled.begin(), c.scaled.end(), p.scale_name) != c.scaled.end())
                p.set(s, p.get(fine) * std::pow(c.sf, similarity::demanded_exponent(p.dimension, c.exponent)));
        }
    for (const auto& key : c.scaled) {
        if (std::find(known.begin(), known.end(), key) == known.end()) {
            std::string names;
            for (const auto& k : known) names += (names.empty() ? "" : ", ") + std::string(k);
            throw InputError("--scale", key, names + " (velocity: the lift speed)");
        }
        if (key == "gravity") s.gravity *= std::pow(c.sf, similarity::demanded_exponent(key, c.exponent, "--scale"));
        if (key == "velocity") s.lift_speed_m_per_s *= std::pow(c.sf, similarity::demanded_exponent(key, c.exponent, "--scale"));
    }
    // The time step keeps its margin to every limit the laws impose (the Rayleigh time grows with R̄).
    const auto fine_limits = dem::time_step_limits(fine, smallest_radius(fine)), coarse_limits = dem::time_step_limits(s, smallest_radius(s));
    for (std::size_t i = 0; i < fine_limits.size(); ++i) {
        const double dt = fine.dt_s * coarse_limits[i].seconds / fine_limits[i].seconds;
        s.dt_s = i == 0 ? dt : std::min(s.dt_s, dt);
    }
    if (!(2 * largest_radius(s) < s.top_diameter_m))
        throw InputError("--sf", format_number(c.sf),
                         "< " + format_number(0.5 * s.top_diameter_m / largest_radius(fine)) +
                             " (a coarse particle must pass the cone's top opening)");
    return s;
}

namespace {

std::vector<std::string> below(const SlumpScene& s, double particles, const GeometryLimits& l) {
    std::vector<std::string> w;
    const double d = 2 * s.radius_m;
    if (s.top_diameter_m < l.opening_diameters * d)
        w.push_back("top opening " + format_short(s.top_diameter_m / d, 2) + " diameters wide (< " + format_short(l.opening_diameters) + ")");
    if (s.fill_height_m < l.fill_diameters * d)
        w.push_back("fill " + format_short(s.fill_height_m / d, 2) + " diameters high (< " + format_short(l.fill_diameters) + ")");
    if (particles < l.particles)
        w.push_back(format_short(particles, 3) + " particles (< " + format_short(l.particles) + ")");
    return w;
}

}  // namespace

std::vector<std::string> geometry_warnings(const SlumpScene& s, std::size_t particles) {
    return below(s, static_cast<double>(particles), {5, 10, 200});
}

bool passes_opening(const SlumpScene& fine, double sf) { return 2 * sf * largest_radius(fine) < fine.top_diameter_m; }

std::vector<std::string> geometry_limits(const SlumpScene& fine, double sf) {
    if (!passes_opening(fine, sf))
        return {(fine.sizes.monodisperse() ? "particles " : "the largest particles ") + format_short(2 * sf * largest_radius(fine) * 1e3, 3) +
                " mm across do not pass the top opening"};
    const auto s = coarse_grained(fine, {sf, 1, {}});  // the limits depend on the radius, not on k
    const double sphere = s.material.density * 4.0 / 3.0 * M_PI * std::pow(s.radius_m, 3) * mean_volume_ratio(s.sizes);  // the mean sphere
    return below(s, std::floor(fill_mass(s) / sphere + 0.5), s.limits);
}

std::vector<double> usable_scale_factors(const SlumpScene& fine, const std::vector<double>& candidates) {
    std::vector<double> usable;
    for (double sf : candidates)
        if (geometry_limits(fine, sf).empty()) usable.push_back(sf);
    return usable;
}

}  // namespace demscale::slump
