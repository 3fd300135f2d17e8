// The threads' shares of the pair list: runs, direct spheres and slabs hand-computed for small
// lists, and on a random cloud checked against a brute-force count of each sphere's threads.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <omp.h>
#include <random>
#include <set>
#include <vector>

#include "dem/pair_shares.hpp"
#include "dem/spatial_order.hpp"

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

TEST_CASE("Pair shares: runs in pair order, and spheres with pairs of two threads or in another thread's run gather", "[dem][threads]") {
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
        // Spheres 0, 1, 2 have their first pair on thread 0, 3 and 4 on thread 1.
        CHECK(s.spheres == std::vector<std::size_t>{0, 3, 5});
    }
    SECTION("alternating pairs: runs of one pair") {
        // Threads 0 1 0 1 0: sphere 0 has pairs on 0 and 1, 1 on 0 only, 2 on 1 and 0, 3 on 1
        // and 0, 4 on 0 only.
        const std::vector<int> owner{0, 1, 0, 1, 0};
        const PairShares s = shares_of(pairs, 5, 2, [&](std::size_t k) { return owner[k]; });
        CHECK(s.runs[0] == Runs{{0, 1}, {2, 3}, {4, 5}});
        CHECK(s.runs[1] == Runs{{1, 2}, {3, 4}});
        // First pairs: 0 and 1 in (0,1) on 0, 2 in (0,2) on 1, 3 in (2,3) on 1, 4 in (3,4) on 0:
        // three spheres for thread 0, two for thread 1, as runs 0-2 and 3-4.
        CHECK(s.spheres == std::vector<std::size_t>{0, 3, 5});
        // Sphere 4's pairs are all thread 0's but it lies in thread 1's run: it gathers too, so
        // that no thread writes at once to another's run. (0,1) adds to 1 at once, (1,2) to 1.
        CHECK(s.gathering == std::vector<std::uint32_t>{0, 2, 3, 4});
        CHECK(s.direct == std::vector<std::uint8_t>{2, 0, 1, 0, 0});
    }
    SECTION("spheres without pairs go with the sphere before them") {
        // Seven spheres, pairs (1,2) on 0, (2,3) and (4,5) on 1: 0 (none, first) and 1, 2 with
        // thread 0; 3, 4, 5 and 6 (none, after 5) with thread 1.
        const std::vector<Pair> few{{1, 2}, {2, 3}, {4, 5}};
        const std::vector<int> owner{0, 1, 1};
        const PairShares s = shares_of(few, 7, 2, [&](std::size_t k) { return owner[k]; });
        CHECK(s.spheres == std::vector<std::size_t>{0, 3, 7});
    }
    SECTION("one thread: one run, every sphere direct") {
        const PairShares s = shares_of(pairs, 5, 1, [](std::size_t) { return 0; });
        CHECK(s.runs[0] == Runs{{0, 5}});
        CHECK(s.direct == std::vector<std::uint8_t>(5, PairShares::both_direct));
        CHECK(s.gathering.empty());
        CHECK(s.spheres == std::vector<std::size_t>{0, 5});
    }
}

TEST_CASE("Pair shares: slabs of equal weight along the longest side", "[dem][threads]") {
    // Nine pairs (k, k+1) whose first spheres stand 1 m apart along one axis: each in a bin of its
    // own. With equal weights the middles lie at 0.5, 1.5, … 8.5 of 9: the first four below half.
    std::vector<Pair> chain;
    for (std::uint32_t k = 0; k < 9; ++k) chain.push_back({k, k + 1});
    for (int axis = 0; axis < 3; ++axis) {
        const Particles p = on_a_line(10, axis);
        CHECK(slab_owner(chain, p, 2, -1, [](std::size_t) { return 1; }) == std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1, 1});
        // The first pair weighs 9 of 17: its middle (4.5) is below half, the next (9.5) above.
        CHECK(slab_owner(chain, p, 2, -1, [](std::size_t k) { return k == 0 ? 9 : 1; }) ==
              std::vector<std::uint8_t>{0, 1, 1, 1, 1, 1, 1, 1, 1});
        // Three slabs of three: thirds at 3 and 6.
        CHECK(slab_owner(chain, p, 3, -1, [](std::size_t) { return 1; }) == std::vector<std::uint8_t>{0, 0, 0, 1, 1, 1, 2, 2, 2});
        // Work at a sphere counts where the sphere lies: 9 at sphere 0 weighs as the first pair's
        // 9 did above; 9 at sphere 9, beyond the pairs' box, counts in the last bin, with pair 8's
        // 1: 10 of 18, its middle (13) above half, all the others' below.
        auto unit = [](std::size_t) { return std::size_t{1}; };
        CHECK(slab_owner(chain, p, 2, -1, unit, [](std::size_t x) { return x == 0 ? 9 : 0; }) ==
              std::vector<std::uint8_t>{0, 1, 1, 1, 1, 1, 1, 1, 1});
        CHECK(slab_owner(chain, p, 2, -1, unit, [](std::size_t x) { return x == 9 ? 9 : 0; }) ==
              std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 1});
    }
}

TEST_CASE("Pair shares: slabs cut the axis they are given, not always the longest side", "[dem][threads]") {
    // First spheres at x = k and y = 0, 10, 2, 12, 4, 14, 6, 16, 8 (y the longest side), one pair
    // each, equal weights: by y the four lowest (k = 0, 2, 4, 6) fall below half, by x k = 0-3.
    const std::vector<double> y{0, 10, 2, 12, 4, 14, 6, 16, 8};
    Particles p;
    for (std::size_t k = 0; k < 9; ++k) p.add(Vec3(static_cast<double>(k), y[k], 0), 0.5, 1.0);
    p.add(Vec3(9, 0, 0), 0.5, 1.0);
    std::vector<Pair> chain;
    for (std::uint32_t k = 0; k < 9; ++k) chain.push_back({k, k + 1});
    auto unit = [](std::size_t) { return 1; };
    CHECK(slab_owner(chain, p, 2, -1, unit) == std::vector<std::uint8_t>{0, 1, 0, 1, 0, 1, 0, 1, 1});
    CHECK(slab_owner(chain, p, 2, 1, unit) == std::vector<std::uint8_t>{0, 1, 0, 1, 0, 1, 0, 1, 1});
    CHECK(slab_owner(chain, p, 2, 0, unit) == std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1, 1});
}

TEST_CASE("Pair shares on a random cloud: each pair once, gathering exactly where a sphere's pairs leave its run's thread",
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
        const auto owner = slab_owner(pairs, p, parts, -1, [](std::size_t) { return 1; });
        const PairShares s = shares_of(pairs, p.size(), parts, [&](std::size_t k) { return owner[k]; });
        for (const int threads : {1, 3}) {  // drawn on other thread counts: the same shares (checked below)
            omp_set_num_threads(threads);
            const PairShares again = shares_of(pairs, p.size(), parts, [&](std::size_t k) { return owner[k]; });
            CHECK(again.runs == s.runs);
            CHECK(again.direct == s.direct);
            CHECK(again.gathering == s.gathering);
            CHECK(again.spheres == s.spheres);
        }
        omp_set_num_threads(omp_get_num_procs());
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
        // Each share's run of spheres is as long as the count of spheres whose first pair it takes
        // (a sphere without pairs counted with the one before).
        std::vector<std::size_t> first_pair(p.size(), pairs.size()), count(parts, 0);
        std::vector<int> first_share(p.size(), 0);
        for (std::size_t k = 0; k < pairs.size(); ++k)
            for (const std::uint32_t x : {pairs[k].i, pairs[k].j})
                if (k < first_pair[x]) first_pair[x] = k, first_share[x] = owner[k];
        for (std::size_t x = 0; x < p.size(); ++x) {
            if (first_pair[x] == pairs.size() && x > 0) first_share[x] = first_share[x - 1];
            ++count[first_share[x]];
        }
        REQUIRE(s.spheres.size() == static_cast<std::size_t>(parts) + 1);
        CHECK(s.spheres.front() == 0);
        for (int t = 0; t < parts; ++t) CHECK(s.spheres[t + 1] - s.spheres[t] == count[t]);
        // A sphere gathers when its pairs span threads or fall to another thread than its run's
        // (runs laid end to end by the counts above); the others get their pairs at once.
        std::vector<int> run_of(p.size());
        for (std::size_t x = 0, t = 0, end = count[0]; x < p.size(); ++x) {
            while (x >= end) end += count[++t];
            run_of[x] = static_cast<int>(t);
        }
        std::vector<std::uint32_t> spanning;
        std::vector<bool> gathers(p.size(), false);
        std::size_t misplaced = 0;
        for (std::uint32_t x = 0; x < p.size(); ++x) {
            const bool elsewhere = threads_of[x].size() == 1 && *threads_of[x].begin() != run_of[x];
            misplaced += elsewhere;
            if (threads_of[x].size() > 1 || elsewhere) spanning.push_back(x), gathers[x] = true;
        }
        CHECK(s.gathering == spanning);
        CHECK(misplaced > 0);  // the cloud is not sorted: the rule is exercised
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            CHECK(((s.direct[k] & 1) != 0) == !gathers[pairs[k].i]);
            CHECK(((s.direct[k] & 2) != 0) == !gathers[pairs[k].j]);
        }
    }
}

TEST_CASE("Pair shares: spheres sorted in layers across the slabs lie in their own thread's run", "[dem][threads][sort]") {
    // The flat cloud of the test above, sorted in layers along its longest side (x), as the engine
    // sorts: each run of spheres is then its slab but for spheres near a cut. In the layers along
    // z, the slabs' spheres lie all over memory and about half would sit in another's run.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    Particles cloud;
    for (int k = 0; k < 2000; ++k) cloud.add(Vec3(0.04 * u(rng), 0.02 * u(rng), 0.004 * u(rng)), 1e-3, 1e-5);
    std::size_t gathering = 0;  // of misplaced's last call
    auto misplaced = [&](int slowest) {
        Particles p = cloud;
        p.reorder(spatial_order(p, 2e-3, slowest));
        std::vector<Pair> pairs;
        for (std::uint32_t i = 0; i < p.size(); ++i)
            for (std::uint32_t j = i + 1; j < p.size(); ++j)
                if ((p.position[i] - p.position[j]).norm() < 2.5e-3) pairs.push_back({i, j});
        const auto owner = slab_owner(pairs, p, 2, 0, [](std::size_t) { return 1; });
        const PairShares s = shares_of(pairs, p.size(), 2, [&](std::size_t k) { return owner[k]; });
        // Spheres in a run not their own: their first pair falls to the other thread.
        std::vector<int> first_share(p.size(), -1);
        for (std::size_t k = 0; k < pairs.size(); ++k)
            for (const std::uint32_t x : {pairs[k].i, pairs[k].j})
                if (first_share[x] < 0) first_share[x] = owner[k];
        std::size_t off = 0;
        for (std::size_t x = 0; x < p.size(); ++x) off += first_share[x] >= 0 && first_share[x] != (x < s.spheres[1] ? 0 : 1);
        gathering = s.gathering.size();
        return off;
    };
    REQUIRE(longest_side(cloud) == 0);
    const std::size_t along = misplaced(2), gathering_along = gathering;
    const std::size_t across = misplaced(0), gathering_across = gathering;
    INFO("misplaced: layers across the slabs " << across << ", along " << along << " of 2000");
    INFO("gathering: " << gathering_across << " and " << gathering_along);
    CHECK(across < 100);   // within a cell (2 mm) of the cut at x = 20 mm: at most a tenth of the cloud
    CHECK(along > 600);
    // Misplaced spheres gather (their thread must not write to another's run): sorted across the
    // slabs, the gathering ones are the cut's neighbourhood (a pair's reach, 2.5 mm, of 40 mm
    // either side, plus the misplaced), not the cloud.
    CHECK(gathering_across < 400);
    CHECK(gathering_along > along);
}

TEST_CASE("Pair shares: slabs follow their threads' measured seconds, a spike ignored", "[dem][threads]") {
    // The chain of nine pairs along x (first spheres at 0 … 8 m), equal weights: the first draw
    // cuts at 4 m (pairs 0-3 and 4-8, weights 4 and 5) and records it.
    std::vector<Pair> chain;
    for (std::uint32_t k = 0; k < 9; ++k) chain.push_back({k, k + 1});
    const Particles p = on_a_line(10, 0);
    auto unit = [](std::size_t) { return 1; };
    SlabCosts costs;
    CHECK(slab_owner(chain, p, 2, 0, unit, NoSphereWork{}, &costs) == std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1, 1});
    CHECK(costs.cuts == std::vector<double>{4.0});
    CHECK(costs.weight == std::vector<double>{4, 5});
    // Four steps: slab 0's thread 2 ms a step but one step of 50 ms (the host took its core away),
    // slab 1's 1.25 ms. By the median step, 0.5 ms per weight against 0.25: the factors 4/3 and
    // 2/3 of the mean (by the mean step slab 0 would weigh 1.87 times its model).
    for (const double ms : {2.0, 50.0, 2.0, 2.0}) costs.took_step(0, ms * 1e-3);
    for (int k = 0; k < 4; ++k) costs.took_step(1, 1.25e-3);
    const std::vector<double> f = costs.factors(2, 0);
    REQUIRE(f.size() == 2);
    CHECK(f[0] == Approx(4.0 / 3));
    CHECK(f[1] == Approx(2.0 / 3));
    CHECK(costs.factors(3, 0).empty());  // another count of slabs, or another axis: no correction
    CHECK(costs.factors(2, 1).empty());
    // Weighed so, the first four pairs cost 16/3 of 26/3: pair 3's middle (14/3) passes half
    // (13/3), and the cut moves to 3 m.
    CHECK(slab_owner(chain, p, 2, 0, unit, NoSphereWork{}, &costs) == std::vector<std::uint8_t>{0, 0, 0, 1, 1, 1, 1, 1, 1});
    CHECK(costs.cuts == std::vector<double>{3.0});
    CHECK(costs.weight == std::vector<double>{3, 6});  // the model's weights, for the next measurement
    CHECK(costs.factors(2, 0).empty());                // nothing measured since this draw
    // A slab with a step of no time (a thread that had nothing) leaves the weights as modelled.
    costs.took_step(0, 1e-3), costs.took_step(1, 0.0);
    CHECK(costs.factors(2, 0).empty());
}
