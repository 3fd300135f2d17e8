#include "slump/fill.hpp"

#include "slump/pour.hpp"

#include <cmath>
#include <random>

namespace demscale::slump {

dem::Particles fill_cone(const SlumpScene& s) {
    const double r = s.radius_m, pitch = 2.02 * r;
    const double layer = pitch * std::sqrt(2.0 / 3.0);  // hcp layer spacing
    std::mt19937 rng(s.seed);
    // ±0.5 % per axis: two neighbours at 2.02 R approach by at most 2√3·0.005 R, so never overlap.
    std::uniform_real_distribution<double> jitter(-0.005 * r, 0.005 * r);
    dem::Particles p;
    const double first = s.rough_floor ? 2.03 * r : 1.01 * r;  // clear of the floor's grains
    for (int k = 0;; ++k) {
        const double z = first + k * layer;
        if (z + r > s.height_m) break;
        // Inside radius of the cone at this height, less the sphere and a clearance.
        const double inner = 0.5 * s.bottom_diameter_m - 0.5 * (s.bottom_diameter_m - s.top_diameter_m) * (z + r) / s.height_m;
        const double reach = inner - 1.05 * r;
        if (reach < 0) continue;
        const double shift_x = (k % 3) * 0.5 * pitch, shift_y = (k % 3) * pitch / (2.0 * std::sqrt(3.0));
        const int rows = static_cast<int>(std::ceil(reach / (pitch * std::sqrt(3.0) / 2))) + 1;
        const int cols = static_cast<int>(std::ceil(reach / pitch)) + 1;
        for (int row = -rows; row <= rows; ++row)
            for (int col = -cols; col <= cols; ++col) {
                const double x = col * pitch + (row % 2 != 0 ? 0.5 * pitch : 0.0) + shift_x - 0.5 * pitch;
                const double y = row * pitch * std::sqrt(3.0) / 2 + shift_y;
                if (std::hypot(x, y) > reach) continue;
                p.add({x + jitter(rng), y + jitter(rng), z + jitter(rng)}, r, s.material.density);
            }
    }
    return cut_to_mass(s, p);
}

}  // namespace demscale::slump

namespace demscale::slump {

dem::Particles floor_grains(const SlumpScene& s) {
    dem::Particles p;
    if (!s.rough_floor) return p;
    const double r = s.radius_m, pitch = 2 * r, row_step = pitch * std::sqrt(3.0) / 2, reach = 0.5 * s.rough_floor_diameter_m;
    std::mt19937 rng(s.seed + 7919u);  // its own stream: the fill's jitter stays the same
    std::uniform_real_distribution<double> jitter(-0.05 * r, 0.05 * r);
    const int rows = static_cast<int>(reach / row_step) + 1, cols = static_cast<int>(reach / pitch) + 1;
    for (int row = -rows; row <= rows; ++row)
        for (int col = -cols; col <= cols; ++col) {
            const double x = col * pitch + (row % 2 != 0 ? 0.5 * pitch : 0.0), y = row * row_step;
            if (std::hypot(x, y) > reach) continue;
            p.add_fixed({x + jitter(rng), y + jitter(rng), 0.0}, r, s.material.density, 1);
        }
    return p;
}

}  // namespace demscale::slump
