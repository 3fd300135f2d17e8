#include "slump/fill_measures.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "dem/sphere_grid.hpp"
#include "slump/measurements.hpp"

namespace demscale::slump {

FillMeasures measure_fill(const dem::Particles& all, const SlumpScene& s) {
    if (all.mobile_count() != all.size()) return measure_fill(all.mobile(), s);
    FillMeasures m;
    const std::size_t n = all.size();
    if (n == 0) return m;
    const double r = all.radius[0];
    double solid = 0;
    for (std::size_t i = 0; i < n; ++i) {
        m.top = std::max(m.top, all.position[i].z() + all.radius[i]);
        solid += 4.0 / 3.0 * M_PI * std::pow(all.radius[i], 3);
        m.mass += all.mass[i];
    }
    m.height = measure_pile(all, s).height;
    m.solid_fraction = solid / cone_volume_below(s, std::min(m.height, s.height_m));

    dem::SphereGrid cells(2 * r);
    for (const auto& x : all.position) cells.add(x);
    // Counts and a maximum: the same on any thread count.
    std::size_t contacts = 0;
    double max_overlap = 0;
    const long count = static_cast<long>(n);
#pragma omp parallel for schedule(static) reduction(+ : contacts) reduction(max : max_overlap)
    for (long ii = 0; ii < count; ++ii) {
        const auto i = static_cast<std::size_t>(ii);
        cells.near(all.position[i], [&](std::size_t j, const dem::Vec3&) {
            if (j <= i) return;
            const double overlap = all.radius[i] + all.radius[j] - (all.position[i] - all.position[j]).norm();
            if (overlap >= 0) ++contacts, max_overlap = std::max(max_overlap, overlap / r);
        });
    }
    m.max_overlap = max_overlap;
    m.coordination = 2.0 * static_cast<double>(contacts) / static_cast<double>(n);

    // Core: one diameter clear of the floor, the top and the cone wall; random points (a fixed
    // generator, so the measure repeats), one per (0.37 R)³ of core volume: no aliasing with a lattice.
    const double z_lo = 2 * r + (s.rough_floor ? 2 * r : 0), z_hi = m.top - 2 * r;
    std::size_t inside = 0;
    if (z_hi > z_lo && cone_radius_at(s, z_hi) > 2 * r) {
        const double reach = cone_radius_at(s, z_lo) - 2 * r;  // the widest, at the bottom
        const auto points = static_cast<std::size_t>(M_PI * reach * reach * (z_hi - z_lo) / std::pow(0.37 * r, 3));
        std::mt19937_64 rng(12345);
        std::uniform_real_distribution<double> u(-1, 1), uz(z_lo, z_hi);
        // Drawn on one thread (the stream fixes the points), tested in blocks on all.
        std::vector<dem::Vec3> block;
        const double cover = std::min(*std::max_element(all.radius.begin(), all.radius.end()), 2 * r);  // m, the largest sphere's reach
        while (m.core_points < points) {
            block.clear();
            while (block.size() < 65536 && m.core_points + block.size() < points) {
                const dem::Vec3 q(reach * u(rng), reach * u(rng), uz(rng));
                const double at = cone_radius_at(s, q.z()) - 2 * r;
                if (q.x() * q.x() + q.y() * q.y() <= at * at) block.push_back(q);
            }
            const long drawn = static_cast<long>(block.size());
#pragma omp parallel for schedule(static) reduction(+ : inside)
            for (long b = 0; b < drawn; ++b) {
                const dem::Vec3& q = block[static_cast<std::size_t>(b)];
                bool covered = false;
                cells.near(q, cover, [&](std::size_t j, const dem::Vec3& x) { covered = covered || (q - x).squaredNorm() < all.radius[j] * all.radius[j]; });
                inside += covered;
            }
            m.core_points += block.size();
        }
    }
    m.core_fraction = m.core_points > 0 ? static_cast<double>(inside) / static_cast<double>(m.core_points) : 0;
    return m;
}

}  // namespace demscale::slump
