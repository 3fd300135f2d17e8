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
    const std::size_t bins = static_cast<std::size_t>(reach / w) + 1;
    // Heights sampled at cell midpoints, a sixteenth of the smallest diameter apart (at most 4 000).
    const double dz = std::max(r_min / 8, top / 4000);
    const std::size_t cells = static_cast<std::size_t>(top / dz) + 1;
    std::vector<double> phi(bins * cells, 0.0);  // phi[b * cells + k]: solid area in annulus b at z_k, m²
    std::vector<double> edge_area(bins + 1);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.radius[i], zc = p.position[i].z();
        if (zc + r <= 0) continue;  // wholly under the floor: no solid above it
        const auto k0 = static_cast<std::size_t>(std::max(0.0, (zc - r) / dz));
        const auto k1 = std::min(cells - 1, static_cast<std::size_t>((zc + r) / dz));
        const auto b0 = static_cast<std::size_t>(std::max(0.0, (rho[i] - r) / w));
        const auto b1 = std::min(bins - 1, static_cast<std::size_t>((rho[i] + r) / w));
        for (std::size_t k = k0; k <= k1; ++k) {
            const double h = (static_cast<double>(k) + 0.5) * dz - zc, a2 = r * r - h * h;
            if (a2 <= 0) continue;
            const double a = std::sqrt(a2);
            // Solid inside radius ρ_e for every annulus edge the section reaches; differences per annulus.
            for (std::size_t e = b0; e <= b1 + 1; ++e) edge_area[e] = e == 0 ? 0 : disc_overlap_area(a, static_cast<double>(e) * w, rho[i]);
            for (std::size_t b = b0; b <= b1; ++b) phi[b * cells + k] += edge_area[b + 1] - edge_area[b];
        }
    }
    s.radii.resize(bins), s.heights.assign(bins, 0.0);
    std::vector<double> column_top(bins, 0.0);
    for (std::size_t b = 0; b < bins; ++b) {
        const double area = std::numbers::pi * w * w * (2 * static_cast<double>(b) + 1);  // π((b+1)² − b²) w²
        s.radii[b] = (static_cast<double>(b) + 0.5) * w;
        for (std::size_t k = 0; k < cells; ++k) {
            phi[b * cells + k] /= area;
            if (phi[b * cells + k] > 0) column_top[b] = (static_cast<double>(k) + 1) * dz;
        }
    }
    // The bulk: each annulus at least 5 radii deep has a plateau, its mean solid fraction between 2
    // radii above the floor and 2 under its top (clear of the floor's layering and of the surface);
    // the pile's bulk is their median, weighted by area, so that annuli the pile covers only in part
    // (its edge, a rim) do not pull it down. Without such an annulus: the whole columns' mean.
    std::vector<std::pair<double, double>> plateaus;  // (plateau, weight)
    double all_sum = 0, all_weight = 0;
    for (std::size_t b = 0; b < bins; ++b) {
        const double area = 2 * static_cast<double>(b) + 1;
        double sum = 0, n = 0;
        for (std::size_t k = 0; k < cells; ++k) {
            const double z = (static_cast<double>(k) + 0.5) * dz, f = phi[b * cells + k];
            if (z <= column_top[b]) all_sum += area * f, all_weight += area;
            if (z >= 2 * r_max && z <= column_top[b] - 2 * r_max) sum += f, n += 1;
        }
        if (column_top[b] >= 5 * r_max && n > 0 && sum > 0) plateaus.emplace_back(sum / n, area * n);
    }
    if (!plateaus.empty()) {
        std::sort(plateaus.begin(), plateaus.end());
        double total = 0, seen = 0;
        for (const auto& [f, weight] : plateaus) total += weight;
        for (const auto& [f, weight] : plateaus)
            if ((seen += weight) >= 0.5 * total) {
                s.bulk_fraction = f;
                break;
            }
    } else if (all_weight > 0) {
        s.bulk_fraction = all_sum / all_weight;
    }
    if (s.bulk_fraction <= 0) return s;
    for (std::size_t b = 0; b < bins; ++b) {
        if (column_top[b] <= 0) continue;
        const double za = std::max(0.0, column_top[b] - 4 * r_max);
        double solid = 0;
        for (std::size_t k = static_cast<std::size_t>(za / dz); k < cells; ++k) solid += phi[b * cells + k] * dz;
        s.heights[b] = std::floor(za / dz) * dz + solid / s.bulk_fraction;
    }
    // Height: the surface's mean over the axis disc, each annulus weighted by its area inside it.
    double sum = 0, weight = 0;
    for (std::size_t b = 0; b < bins && static_cast<double>(b) * w < grid.axis_radius; ++b) {
        const double outer = std::min(static_cast<double>(b + 1) * w, grid.axis_radius), inner = static_cast<double>(b) * w;
        sum += (outer * outer - inner * inner) * s.heights[b], weight += outer * outer - inner * inner;
    }
    s.height = sum / weight;
    // Spread: the outermost crossing of spread_level × height, outward.
    const double level = spread_level * s.height;
    for (std::size_t b = bins; b-- > 0;) {
        if (s.heights[b] < level) continue;
        if (b + 1 == bins) {
            s.spread = 2 * static_cast<double>(bins) * w;
        } else {
            const double t = (s.heights[b] - level) / (s.heights[b] - s.heights[b + 1]);
            s.spread = 2 * (s.radii[b] + t * w);
        }
        break;
    }
    return s;
}

}  // namespace demscale::slump
