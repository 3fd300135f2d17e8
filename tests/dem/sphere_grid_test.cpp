// The sphere grid's queries against brute force: every centre within the reach is visited, once,
// and a reach of half a cell looks in at most 8 cells.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "dem/sphere_grid.hpp"

using namespace demscale::dem;

TEST_CASE("Sphere grid: a query finds every centre within its reach, once, in at most 8 cells for half a cell", "[dem][fill]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.01, 0.01);
    const double cell = 2e-3;
    SphereGrid grid(cell);
    std::vector<Vec3> centres(3000);
    for (auto& x : centres) x = Vec3(u(rng), u(rng), u(rng)), grid.add(x);
    std::size_t most_half = 0;
    for (int q = 0; q < 2000; ++q) {
        const Vec3 x(u(rng), u(rng), u(rng));
        for (const double reach : {0.3 * cell, 0.5 * cell, cell}) {
            std::multiset<std::size_t> seen;
            std::set<long long> cells;
            grid.near(x, reach, [&](std::size_t k, const Vec3& y) {
                seen.insert(k);
                CHECK(y == centres[k]);
                cells.insert(static_cast<long long>(std::floor(y.x() / cell)) * 1000000 + static_cast<long long>(std::floor(y.y() / cell)) * 1000 +
                             static_cast<long long>(std::floor(y.z() / cell)));
            });
            bool all_found = true, once = true;
            for (std::size_t k = 0; k < centres.size(); ++k) {
                if ((centres[k] - x).norm() < reach) all_found = all_found && seen.count(k) == 1;
                once = once && seen.count(k) <= 1;
            }
            CHECK(all_found);
            CHECK(once);
            if (reach == 0.5 * cell) most_half = std::max(most_half, cells.size());
            bool any = false;
            for (const auto& y : centres) any = any || (y - x).norm() < reach;
            CHECK(grid.any_within(x, reach) == any);
        }
    }
    CHECK(most_half <= 8);
    CHECK(most_half >= 2);
}
