#include "core/core_link.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <omp.h>
#include <random>
#include <vector>

namespace demscale {

namespace {
struct alignas(64) Line {
    double value[8];
};
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

std::optional<CoreLink> measure_core_link() {
    // Two halves of 4 000 lines (256 kB each, within a core's own cache), visited in a shuffled
    // order so that no prefetcher hides a line's trip.
    constexpr std::size_t lines = 4000;
    constexpr int rounds = 1500;
    std::vector<Line> halves(2 * lines, Line{});
    std::vector<std::uint32_t> order(lines);
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), std::mt19937(1));
    auto per_line_ns = [&](bool crossing) {
        bool two = true;
        const auto start = Clock::now();
#pragma omp parallel num_threads(2)
        {
            if (omp_get_num_threads() < 2) {
#pragma omp single
                two = false;
            } else {
                const int thread = omp_get_thread_num();
                for (int round = 0; round < rounds; ++round) {
                    Line* half = halves.data() + lines * static_cast<std::size_t>(crossing ? (round + thread) % 2 : thread);
                    for (const std::uint32_t k : order) half[k].value[0] += 1.0;
#pragma omp barrier
                }
            }
        }
        return two ? seconds_since(start) * 1e9 / (double(rounds) * double(lines)) : -1.0;
    };
    CoreLink link{per_line_ns(false), per_line_ns(true), 0};
    if (link.kept_ns < 0 || link.crossing_ns < 0) return std::nullopt;
    constexpr int regions = 100000;
    std::atomic<long> entered{0};  // a body the compiler cannot drop
    const auto start = Clock::now();
    for (int r = 0; r < regions; ++r) {
#pragma omp parallel num_threads(2)
        entered.fetch_add(1, std::memory_order_relaxed);
    }
    link.region_us = seconds_since(start) * 1e6 / regions;
    if (entered.load() != 2L * regions) return std::nullopt;  // a region ran on one thread
    return link;
}

}  // namespace demscale
