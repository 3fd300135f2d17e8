// Points (sphere centres) binned in cubic cells, for "which centres lie near x" without a neighbour
// list: the pour's overlap test while it inserts, and the fill measures' contacts and coverage.
// A query visits the 27 cells around x, so it finds every centre within one cell size of x.
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
    void add(const Vec3& x) { cells_[key(x, 0, 0, 0)].push_back({count_++, x}); }

    // visit(index, centre) for every centre in the 27 cells around x.
    template <class Visit>
    void near(const Vec3& x, Visit visit) const {
        for (int i = -1; i <= 1; ++i)
            for (int j = -1; j <= 1; ++j)
                for (int k = -1; k <= 1; ++k)
                    if (const auto it = cells_.find(key(x, i, j, k)); it != cells_.end())
                        for (const auto& [index, y] : it->second) visit(index, y);
    }

    // Whether a centre lies closer to x than distance (≤ the cell size).
    bool any_within(const Vec3& x, double distance) const {
        bool found = false;
        near(x, [&](std::size_t, const Vec3& y) { found = found || (x - y).squaredNorm() < distance * distance; });
        return found;
    }

private:
    long long key(const Vec3& x, int i, int j, int k) const {
        auto c = [&](double v, int d) { return static_cast<long long>(std::floor(v / cell_)) + d + (1 << 20); };
        return (c(x.x(), i) << 42) | (c(x.y(), j) << 21) | c(x.z(), k);
    }
    double cell_;
    std::size_t count_ = 0;
    std::unordered_map<long long, std::vector<std::pair<std::size_t, Vec3>>> cells_;
};

}  // namespace demscale::dem
