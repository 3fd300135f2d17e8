#include "slump/pile_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace demscale::slump {

double disc_overlap_area(double a, double b, double d) {
    constexpr double pi = std::numbers::pi;
    if (a <= 0 || b <= 0 || d >= a + b) return 0;
    if (d <= std::abs(a - b)) return pi * std::min(a, b) * std::min(a, b);
    // Two circular segments, one of each disc, cut by the common chord.
    const double ca = std::clamp((d * d + a * a - b * b) / (2 * d * a), -1.0, 1.0);
    const double cb = std::clamp((d * d + b * b - a * a) / (2 * d * b), -1.0, 1.0);
    const double k = std::max(0.0, (-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b));
    return a * a * std::acos(ca) + b * b * std::acos(cb) - 0.5 * std::sqrt(k);
}

namespace {

// The solid fraction φ(z) of every annulus, sampled at cell midpoints a sixteenth of the smallest
// diameter apart (at most 4 000 cells), from the exact areas of the spheres' sections.
struct SolidField {
    double w = 0, dz = 0;
    std::size_t bins = 0, cells = 0;
    std::vector<double> phi;         // phi[b * cells + k]
    std::vector<double> column_top;  // per annulus: the top of its highest cell holding solid, m (0: empty)
    double at(std::size_t b, std::size_t k) const { return phi[b * cells + k]; }
    double z(std::size_t k) const { return (static_cast<double>(k) + 0.5) * dz; }
    double radius(std::size_t b) const { return (static_cast<double>(b) + 0.5) * w; }
};

SolidField solid_field(const dem::Particles& p, const std::vector<double>& rho, double w, double top, double reach, double r_min) {
    SolidField f;
    f.w = w, f.bins = static_cast<std::size_t>(reach / w) + 1;
    f.dz = std::max(r_min / 8, top / 4000), f.cells = static_cast<std::size_t>(top / f.dz) + 1;
    f.phi.assign(f.bins * f.cells, 0.0);
    std::vector<double> inside(f.bins + 1);  // section area inside each annulus edge
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.radius[i], zc = p.position[i].z();
        if (zc + r <= 0) continue;  // wholly under the floor: no solid above it
        const auto k0 = static_cast<std::size_t>(std::max(0.0, (zc - r) / f.dz));
        const auto k1 = std::min(f.cells - 1, static_cast<std::size_t>((zc + r) / f.dz));
        const auto b0 = static_cast<std::size_t>(std::max(0.0, (rho[i] - r) / w));
        const auto b1 = std::min(f.bins - 1, static_cast<std::size_t>((rho[i] + r) / w));
        for (std::size_t k = k0; k <= k1; ++k) {
            const double h = f.z(k) - zc, a2 = r * r - h * h;
            if (a2 <= 0) continue;
            const double a = std::sqrt(a2);
            for (std::size_t e = b0; e <= b1 + 1; ++e) inside[e] = e == 0 ? 0 : disc_overlap_area(a, static_cast<double>(e) * w, rho[i]);
            for (std::size_t b = b0; b <= b1; ++b) f.phi[b * f.cells + k] += inside[b + 1] - inside[b];
        }
    }
    f.column_top.assign(f.bins, 0.0);
    for (std::size_t b = 0; b < f.bins; ++b) {
        const double area = std::numbers::pi * w * w * (2 * static_cast<double>(b) + 1);  // π((b+1)² − b²) w²
        for (std::size_t k = 0; k < f.cells; ++k) {
            f.phi[b * f.cells + k] /= area;
            if (f.at(b, k) > 0) f.column_top[b] = (static_cast<double>(k) + 1) * f.dz;
        }
    }
    return f;
}

// The pile's bulk solid fraction: each annulus at least 5 radii deep has a plateau, its mean solid
// fraction between 2 radii above the floor and 2 under its top (clear of the floor's layering and of
// the surface); the bulk is their median, weighted by area, so that annuli the pile covers only in
// part (its edge, a rim) do not pull it down. Without such an annulus: the whole columns' mean.
double bulk_fraction(const SolidField& f, double r_max) {
    std::vector<std::pair<double, double>> plateaus;  // (plateau, weight)
    double all_sum = 0, all_weight = 0;
    for (std::size_t b = 0; b < f.bins; ++b) {
        const double area = 2 * static_cast<double>(b) + 1;
        double sum = 0, n = 0;
        for (std::size_t k = 0; k < f.cells; ++k) {
            const double z = f.z(k);
            if (z <= f.column_top[b]) all_sum += area * f.at(b, k), all_weight += area;
            if (z >= 2 * r_max && z <= f.column_top[b] - 2 * r_max) sum += f.at(b, k), n += 1;
        }
        if (f.column_top[b] >= 5 * r_max && n > 0 && sum > 0) plateaus.emplace_back(sum / n, area * n);
    }
    if (plateaus.empty()) return all_weight > 0 ? all_sum / all_weight : 0;
    std::sort(plateaus.begin(), plateaus.end());
    double total = 0, seen = 0;
    for (const auto& [fraction, weight] : plateaus) total += weight;
    for (const auto& [fraction, weight] : plateaus)
        if ((seen += weight) >= 0.5 * total) return fraction;
    return plateaus.back().first;
}

// Each annulus' Gibbs dividing surface against the bulk, from four radii under its highest solid.
std::vector<double> surface_heights(const SolidField& f, double bulk, double r_max) {
    std::vector<double> h(f.bins, 0.0);
    for (std::size_t b = 0; b < f.bins; ++b) {
        if (f.column_top[b] <= 0) continue;
        const auto first = static_cast<std::size_t>(std::max(0.0, f.column_top[b] - 4 * r_max) / f.dz);
        double solid = 0;
        for (std::size_t k = first; k < f.cells; ++k) solid += f.at(b, k) * f.dz;
        h[b] = static_cast<double>(first) * f.dz + solid / bulk;
    }
    return h;
}

// The heights' mean over the disc of radius `axis`, each annulus weighted by its area inside it.
double axis_mean(const std::vector<double>& heights, double w, double axis) {
    double sum = 0, weight = 0;
    for (std::size_t b = 0; b < heights.size() && static_cast<double>(b) * w < axis; ++b) {
        const double outer = std::min(static_cast<double>(b + 1) * w, axis), inner = static_cast<double>(b) * w;
        sum += (outer * outer - inner * inner) * heights[b], weight += outer * outer - inner * inner;
    }
    return weight > 0 ? sum / weight : 0;
}

// Twice the outermost radius where the heights cross `level`, linear between annulus centres.
double diameter_at(const std::vector<double>& heights, double w, double level) {
    for (std::size_t b = heights.size(); b-- > 0;) {
        if (heights[b] < level) continue;
        if (b + 1 == heights.size()) return 2 * static_cast<double>(heights.size()) * w;
        const double t = (heights[b] - level) / (heights[b] - heights[b + 1]);
        return 2 * ((static_cast<double>(b) + 0.5) * w + t * w);
    }
    return 0;
}

}  // namespace

PileSurface pile_surface(const dem::Particles& p, double cx, double cy, const SurfaceGrid& grid) {
    const double w = grid.bin_width;
    if (!(w > 0) || !(grid.axis_radius > 0)) throw std::invalid_argument("pile_surface: bin width and axis radius must be positive");
    PileSurface s;
    if (p.size() == 0) return s;
    double top = 0, reach = 0, r_min = p.radius[0], r_max = p.radius[0];
    std::vector<double> rho(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.radius[i];
        rho[i] = std::hypot(p.position[i].x() - cx, p.position[i].y() - cy);
        top = std::max(top, p.position[i].z() + r), reach = std::max(reach, rho[i] + r);
        r_min = std::min(r_min, r), r_max = std::max(r_max, r);
    }
    const auto field = solid_field(p, rho, w, top, reach, r_min);
    s.radii.resize(field.bins);
    for (std::size_t b = 0; b < field.bins; ++b) s.radii[b] = field.radius(b);
    s.bulk_fraction = bulk_fraction(field, r_max);
    if (s.bulk_fraction <= 0) {
        s.heights.assign(field.bins, 0.0);
        return s;
    }
    s.heights = surface_heights(field, s.bulk_fraction, r_max);
    s.height = axis_mean(s.heights, w, grid.axis_radius);
    s.spread = diameter_at(s.heights, w, spread_level * s.height);
    return s;
}

}  // namespace demscale::slump
