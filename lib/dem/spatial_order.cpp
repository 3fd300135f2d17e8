#include "dem/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace demscale::dem {

std::vector<std::uint32_t> spatial_order(const Particles& p, double cell) {
    const std::size_t n = p.size();
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    if (n < 2) return order;
    Vec3 lo = p.position[0], hi = p.position[0];
    for (const auto& x : p.position) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    // At most 2^21 cells per axis (a far stray sphere shares the last one: the order stays valid,
    // as it does for a non-finite position, which the engine refuses before it sorts).
    constexpr double last = (1 << 21) - 1;
    auto cell_of = [&](double x, int a) {
        const double c = (x - lo[a]) / cell;
        return static_cast<std::uint64_t>(c >= 0 ? std::min(last, std::floor(c)) : 0.0);
    };
    const std::uint64_t nx = cell_of(hi.x(), 0) + 1, ny = cell_of(hi.y(), 1) + 1;
    std::vector<std::uint64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& x = p.position[i];
        key[i] = (cell_of(x.z(), 2) * ny + cell_of(x.y(), 1)) * nx + cell_of(x.x(), 0);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    return order;
}

}  // namespace demscale::dem
