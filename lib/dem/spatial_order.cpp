#include "dem/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace demscale::dem {

namespace {
struct Box {
    Vec3 lo, hi;
};
Box box_around(const Particles& p) {  // p not empty
    Box b{p.position[0], p.position[0]};
    for (const auto& x : p.position) b.lo = b.lo.cwiseMin(x), b.hi = b.hi.cwiseMax(x);
    return b;
}
}  // namespace

int longest_side(const Particles& p) {
    if (p.size() == 0) return 2;
    const Box b = box_around(p);
    int axis = 2;
    (b.hi - b.lo).maxCoeff(&axis);
    return axis;
}

std::vector<std::uint32_t> spatial_order(const Particles& p, double cell, int slowest) {
    const std::size_t n = p.size();
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    if (n < 2) return order;
    const Box box = box_around(p);
    const Vec3 lo = box.lo, hi = box.hi;
    // At most 2^21 cells per axis (a far stray sphere shares the last one: the order stays valid,
    // as it does for a non-finite position, which the engine refuses before it sorts).
    constexpr double last = (1 << 21) - 1;
    auto cell_of = [&](double x, int a) {
        const double c = (x - lo[a]) / cell;
        return static_cast<std::uint64_t>(c >= 0 ? std::min(last, std::floor(c)) : 0.0);
    };
    const int fast = slowest == 0 ? 1 : 0, middle = slowest == 2 ? 1 : 2;
    const std::uint64_t n_fast = cell_of(hi[fast], fast) + 1, n_middle = cell_of(hi[middle], middle) + 1;
    std::vector<std::uint64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& x = p.position[i];
        key[i] = (cell_of(x[slowest], slowest) * n_middle + cell_of(x[middle], middle)) * n_fast + cell_of(x[fast], fast);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    return order;
}

}  // namespace demscale::dem
