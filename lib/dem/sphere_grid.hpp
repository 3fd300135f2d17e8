// Points (sphere centres) binned in cubic cells, for "which centres lie near x" without a neighbour
// list: the pour's overlap test while it inserts, and the fill measures' contacts and coverage.
// A query visits the cells around x that a given reach touches (27 for a reach of one cell size),
// so it finds every centre within that reach of x.
#pragma once

#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dem/particles.hpp"

namespace demscale::dem {

class SphereGrid {
public:
    explicit SphereGrid(double cell) : cell_(cell) {}

    // Adds a centre (m); its index is the count added before it.
    void add(const Vec3& x) { cells_[key(cell_of(x.x()), cell_of(x.y()), cell_of(x.z()))].push_back({count_++, x}); }

    // visit(index, centre) for every centre in the 27 cells around x.
    template <class Visit>
    void near(const Vec3& x, Visit visit) const {
        near(x, cell_, visit);
    }
    // visit(index, centre) for every centre in the cells the cube of half side `reach` (≤ the
    // cell size) about x touches: every centre within reach of x, and some farther. A reach of
    // half a cell touches 8 cells or fewer, not 27.
    template <class Visit>
    void near(const Vec3& x, double reach, Visit visit) const {
        auto cells = [&](int axis) { return std::pair(cell_of(x[axis] - reach), cell_of(x[axis] + reach)); };
        const auto [x0, x1] = cells(0);
        const auto [y0, y1] = cells(1);
        const auto [z0, z1] = cells(2);
        for (long long i = x0; i <= x1; ++i)
            for (long long j = y0; j <= y1; ++j)
                for (long long k = z0; k <= z1; ++k)
                    if (const auto it = cells_.find(key(i, j, k)); it != cells_.end())
                        for (const auto& [index, y] : it->second) visit(index, y);
    }

    // Whether a centre lies closer to x than distance (≤ the cell size).
    bool any_within(const Vec3& x, double distance) const {
        bool found = false;
        near(x, distance, [&](std::size_t, const Vec3& y) { found = found || (x - y).squaredNorm() < distance * distance; });
        return found;
    }

private:
    long long cell_of(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
    static long long key(long long i, long long j, long long k) {
        constexpr long long offset = 1 << 20;
        return ((i + offset) << 42) | ((j + offset) << 21) | (k + offset);
    }
    double cell_;
    std::size_t count_ = 0;
    std::unordered_map<long long, std::vector<std::pair<std::size_t, Vec3>>> cells_;
};

}  // namespace demscale::dem
