// Splitting a loop's items among threads as runs of consecutive items of about equal work, where
// an item that acted last step (a contact that touched) weighs many that were only checked. Runs
// keep each thread's spheres together in memory; the weights only move the run boundaries, never
// what an item computes, so the results are the same bits for any split.
#pragma once

#include <cstddef>
#include <vector>

namespace demscale::dem {

// A checked item weighs 1, one with an acting contact 1 + the cost below: a contact that acts runs
// the whole contact law, one apart only a distance test. A sphere checked against the walls costs
// about twice a listed pair's test, so its contacts weigh half (measured balances in
// docs/performance.md).
inline constexpr std::size_t acting_cost = 16;      // per acting pair
inline constexpr std::size_t wall_acting_cost = 8;  // per acting wall contact of a sphere
// The same in listed pairs' tests, for slabs that weigh pairs and walls together (pair_shares.hpp):
// a sphere checked against the walls weighs two tests, each acting wall contact a pair's law.
inline constexpr std::size_t wall_check_in_pair_tests = 2;

// split (resized to parts + 1): run t is [split[t], split[t + 1]) of the n items, the runs of
// about equal weight. acting(k): how many of item k's contacts acted (0 for none), read only when
// extra > 0; extra: what an acting contact adds to its item's weight (0: equal counts).
template <class Acting>
void split_by_work(std::vector<std::size_t>& split, std::size_t n, int parts, std::size_t extra, Acting acting) {
    split.assign(static_cast<std::size_t>(parts) + 1, n);
    split[0] = 0;
    if (parts < 2) return;
    std::size_t total = n;
    if (extra > 0)
        for (std::size_t k = 0; k < n; ++k) total += extra * acting(k);
    std::size_t done = 0, k = 0;
    for (int t = 1; t < parts; ++t) {
        const std::size_t target = total * static_cast<std::size_t>(t) / static_cast<std::size_t>(parts);
        for (; k < n && done < target; ++k) done += 1 + (extra > 0 ? extra * acting(k) : 0);
        split[static_cast<std::size_t>(t)] = k;
    }
}

}  // namespace demscale::dem
