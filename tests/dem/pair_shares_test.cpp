// The threads' shares of the pair list: runs, direct spheres and slabs hand-computed for small
// lists, and on a random cloud checked against a brute-force count of each sphere's threads.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "dem/pair_shares.hpp"

using namespace demscale::dem;

namespace {
struct Pair {
    std::uint32_t i, j;
};
using Runs = std::vector<PairShares::Run>;

Particles on_a_line(std::size_t n, int axis) {
    Particles p;
    for (std::size_t k = 0; k < n; ++k) {
        Vec3 x = Vec3::Zero();
        x[axis] = static_cast<double>(k);
        p.add(x, 0.5, 1.0);
    }
    return p;
}
}  // namespace

TEST_CASE("Pair shares: runs in pair order, and only spheres with pairs of two threads gather", "[dem][threads]") {
    // Spheres 0-4 in a chain with a triangle: pairs (0,1) (0,2) (1,2) (2,3) (3,4).
    const std::vector<Pair> pairs{{0, 1}, {0, 2}, {1, 2}, {2, 3}, {3, 4}};
    SECTION("two blocks: sphere 2 has pairs on both threads") {
        const std::vector<int> owner{0, 0, 0, 1, 1};
        const PairShares s = shares_of(pairs, 5, 2, [&](std::size_t k) { return owner[k]; });
        CHECK(s.runs[0] == Runs{{0, 3}});
        CHECK(s.runs[1] == Runs{{3, 5}});
        // (0,2) and (1,2) add to their first sphere at once, (2,3) to its second; 2 gathers.
        CHECK(s.direct == std::vector<std::uint8_t>{3, 1, 1, 2, 3});
        CHECK(s.gathering == std::vector<std::uint32_t>{2});
    }
    SECTION("alternating pairs: runs of one pair") {
        // Threads 0 1 0 1 0: sphere 0 has pairs on 0 and 1, 1 on 0 only, 2 on 1 and 0, 3 on 1
        // and 0, 4 on 0 only; so (0,1) adds to 1 at once, (1,2) to 1, (3,4) to 4.
        const std::vector<int> owner{0, 1, 0, 1, 0};
        const PairShares s = shares_of(pairs, 5, 2, [&](std::size_t k) { return owner[k]; });
        CHECK(s.runs[0] == Runs{{0, 1}, {2, 3}, {4, 5}});
        CHECK(s.runs[1] == Runs{{1, 2}, {3, 4}});
        CHECK(s.gathering == std::vector<std::uint32_t>{0, 2, 3});
        CHECK(s.direct == std::vector<std::uint8_t>{2, 0, 1, 0, 2});
    }
    SECTION("one thread: one run, every sphere direct") {
        const PairShares s = shares_of(pairs, 5, 1, [](std::size_t) { return 0; });
        CHECK(s.runs[0] == Runs{{0, 5}});
        CHECK(s.direct == std::vector<std::uint8_t>(5, PairShares::both_direct));
        CHECK(s.gathering.empty());
    }
}

TEST_CASE("Pair shares: slabs of equal weight along the longest side", "[dem][threads]") {
    // Nine pairs (k, k+1) whose first spheres stand 1 m apart along one axis: each in a bin of its
    // own. With equal weights the middles lie at 0.5, 1.5, … 8.5 of 9: the first four below half.
    std::vector<Pair> chain;
    for (std::uint32_t k = 0; k < 9; ++k) chain.push_back({k, k + 1});
    for (int axis = 0; axis < 3; ++axis) {
        const Particles p = on_a_line(10, axis);
        CHECK(slab_owner(chain, p, 2, [](std::size_t) { return 1; }) == std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1, 1});
        // The first pair weighs 9 of 17: its middle (4.5) is below half, the next (9.5) above.
        CHECK(slab_owner(chain, p, 2, [](std::size_t k) { return k == 0 ? 9 : 1; }) ==
              std::vector<std::uint8_t>{0, 1, 1, 1, 1, 1, 1, 1, 1});
        // Three slabs of three: thirds at 3 and 6.
        CHECK(slab_owner(chain, p, 3, [](std::size_t) { return 1; }) == std::vector<std::uint8_t>{0, 0, 0, 1, 1, 1, 2, 2, 2});
    }
}

TEST_CASE("Pair shares on a random cloud: each pair once, gathering exactly where a sphere's pairs span threads",
          "[dem][threads]") {
    // 2000 spheres in a flat box 40 x 20 x 4 mm, pairs closer than 2.5 mm: the slabs cut along x.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    Particles p;
    for (int k = 0; k < 2000; ++k) p.add(Vec3(0.04 * u(rng), 0.02 * u(rng), 0.004 * u(rng)), 1e-3, 1e-5);
    std::vector<Pair> pairs;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t j = i + 1; j < p.size(); ++j)
            if ((p.position[i] - p.position[j]).norm() < 2.5e-3) pairs.push_back({i, j});
    for (const int parts : {2, 3, 4}) {
        const auto owner = slab_owner(pairs, p, parts, [](std::size_t) { return 1; });
        const PairShares s = shares_of(pairs, p.size(), parts, [&](std::size_t k) { return owner[k]; });
        std::vector<int> seen(pairs.size(), 0);
        std::vector<std::set<int>> threads_of(p.size());
        for (int t = 0; t < parts; ++t) {
            std::size_t last = 0, count = 0;
            for (const auto& [first, end] : s.runs[t])
                for (std::size_t k = first; k < end; ++k) {
                    CHECK((count == 0 || k > last));  // ascending
                    last = k, ++count, ++seen[k];
                    CHECK(owner[k] == t);
                    threads_of[pairs[k].i].insert(t), threads_of[pairs[k].j].insert(t);
                }
            // Equal weights: each slab within a few bins' pairs of an equal share.
            const double share = static_cast<double>(pairs.size()) / parts;
            CHECK(std::abs(static_cast<double>(count) - share) < 0.05 * share * parts);
        }
        CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(pairs.size()));
        std::vector<std::uint32_t> spanning;
        for (std::uint32_t x = 0; x < p.size(); ++x)
            if (threads_of[x].size() > 1) spanning.push_back(x);
        CHECK(s.gathering == spanning);
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            CHECK(((s.direct[k] & 1) != 0) == (threads_of[pairs[k].i].size() == 1));
            CHECK(((s.direct[k] & 2) != 0) == (threads_of[pairs[k].j].size() == 1));
        }
        // Slabs across the 40 mm side: the spheres within a pair's reach of a cut, not the cloud.
        CHECK(static_cast<double>(s.gathering.size()) < 0.2 * (parts - 1) * static_cast<double>(p.size()));
    }
}
