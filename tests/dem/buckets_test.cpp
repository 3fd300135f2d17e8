// The counting sort of the rebuilds (buckets.hpp) against a stable comparison sort of the same
// keys, on one to four threads, for dense and sparse buckets, few items and many.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <omp.h>
#include <random>
#include <vector>

#include "dem/buckets.hpp"

using namespace demscale::dem;

TEST_CASE("Buckets: the items in key order and equal keys in item order on any number of threads", "[dem][threads]") {
    std::mt19937 rng(11);
    struct Case {
        std::size_t count, buckets;
    };
    // Below the parallel threshold; dense (ten items a bucket); about one a bucket; sparse (a
    // grid mostly empty: fewer threads count it); a single bucket; no items.
    for (const Case c : {Case{300, 40}, Case{20000, 2000}, Case{5000, 5000}, Case{3000, 200000}, Case{4000, 1}, Case{0, 7}}) {
        std::uniform_int_distribution<std::size_t> draw(0, c.buckets - 1);
        std::vector<std::size_t> key(c.count);
        for (auto& k : key) k = draw(rng);
        std::vector<std::uint32_t> expected(c.count);
        std::iota(expected.begin(), expected.end(), 0u);
        std::stable_sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
        for (const int threads : {1, 2, 3, 4}) {
            omp_set_num_threads(threads);
            const Buckets b = bucket_by(c.count, c.buckets, [&](std::size_t e) { return key[e]; });
            INFO(c.count << " items in " << c.buckets << " buckets on " << threads << " threads");
            CHECK(b.order == expected);
            REQUIRE(b.start.size() == c.buckets + 1);
            CHECK(b.start.front() == 0);
            CHECK(b.start.back() == c.count);
            // Bucket k holds exactly the items of key k (brute force over the items).
            bool holds = true;
            for (std::size_t k = 0; k < c.buckets && holds; ++k)
                for (std::uint32_t at = b.start[k]; at < b.start[k + 1]; ++at) holds = holds && key[b.order[at]] == k;
            CHECK(holds);
        }
    }
    omp_set_num_threads(omp_get_num_procs());
}
