// The threads' runs of a loop: boundaries hand-computed from the weights.
#include <catch2/catch.hpp>
#include <vector>

#include "dem/work_split.hpp"

using namespace demscale::dem;

TEST_CASE("Runs of equal work: acting items weigh more, runs cover every item once", "[dem][threads]") {
    std::vector<std::size_t> split;
    auto none = [](std::size_t) { return std::size_t{0}; };

    SECTION("equal counts without weights") {
        // 10 items in 3 runs: targets 10·1/3 = 3 and 10·2/3 = 6.
        split_by_work(split, 10, 3, 0, none);
        CHECK(split == std::vector<std::size_t>{0, 3, 6, 10});
    }
    SECTION("items that acted move the boundary towards them") {
        // Items 0-2 acted (weight 1 + 3 = 4), items 3-9 were only checked (1): total 12 + 7 = 19,
        // half 19/2 = 9 (integer): 4, 8, then 12 ≥ 9 after item 2, so run 0 is items 0-2.
        const std::vector<std::size_t> acted{1, 1, 1, 0, 0, 0, 0, 0, 0, 0};
        split_by_work(split, 10, 2, 3, [&](std::size_t k) { return acted[k]; });
        CHECK(split == std::vector<std::size_t>{0, 3, 10});
    }
    SECTION("an item with two acting contacts (a sphere on two walls) counts both") {
        // Weights 1 + 2·5 = 11, then 1 × 9: total 20, half 10: item 0 alone reaches it.
        const std::vector<std::size_t> acted{2, 0, 0, 0, 0, 0, 0, 0, 0, 0};
        split_by_work(split, 10, 2, 5, [&](std::size_t k) { return acted[k]; });
        CHECK(split == std::vector<std::size_t>{0, 1, 10});
    }
    SECTION("more runs than items, and one run") {
        split_by_work(split, 2, 4, 0, none);
        CHECK(split == std::vector<std::size_t>{0, 0, 1, 1, 2});
        split_by_work(split, 7, 1, 16, none);
        CHECK(split == std::vector<std::size_t>{0, 7});
    }
}
