#include "report/table1_particles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace demscale::report {

namespace {
double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }
}  // namespace

DensityFit fit_density(const std::vector<double>& radii_m, const std::vector<double>& masses_kg,
                       double mass_resolution_kg) {
    DensityFit fit;
    double mv = 0, vv = 0, lo = 0, hi = INFINITY;
    for (std::size_t i = 0; i < radii_m.size(); ++i) {
        const double v = sphere_volume(radii_m[i]);
        mv += masses_kg[i] * v;
        vv += v * v;
        lo = std::max(lo, (masses_kg[i] - 0.5 * mass_resolution_kg) / v);
        hi = std::min(hi, (masses_kg[i] + 0.5 * mass_resolution_kg) / v);
    }
    fit.least_squares_kg_per_m3 = mv / vv;
    if (lo <= hi) fit.consistent_min_kg_per_m3 = lo, fit.consistent_max_kg_per_m3 = hi;
    return fit;
}

Table1Particles table1_particles(const io::TableConfig& c) {
    Table1Particles p;
    if (!c.tabulated_masses_kg.empty()) p.fit = fit_density(c.radii_m, c.tabulated_masses_kg, c.mass_resolution_kg);
    p.solid_density_kg_per_m3 = c.solid_density_kg_per_m3 ? *c.solid_density_kg_per_m3 : p.fit->least_squares_kg_per_m3;

    auto tabulated_at = [&](double radius) -> std::optional<double> {
        for (std::size_t i = 0; i < c.tabulated_masses_kg.size(); ++i)
            if (std::abs(c.radii_m[i] - radius) <= 1e-12 * radius) return c.tabulated_masses_kg[i];
        return std::nullopt;
    };
    auto particle = [&](double radius) {
        const double sf = radius / c.physical_radius_m;
        const auto tab = tabulated_at(radius);
        if (c.mass_source == io::MassSource::table && tab) return similarity::describe_particle(sf, radius, *tab, c.liquid);
        return similarity::replace_particle(c.physical_radius_m, p.solid_density_kg_per_m3, sf, c.liquid);
    };
    p.physical = particle(c.physical_radius_m);
    for (std::size_t i = 0; i < c.radii_m.size(); ++i) {
        p.rows.push_back(particle(c.radii_m[i]));
        p.tabulated_mass_kg.push_back(i < c.tabulated_masses_kg.size() ? std::optional(c.tabulated_masses_kg[i])
                                                                       : std::nullopt);
    }
    return p;
}

}  // namespace demscale::report
