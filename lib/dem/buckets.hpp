// A counting sort on all threads: items 0 … count-1 in ascending key order, equal keys in item
// order, for the neighbour grid's cells, the neighbour pairs by first sphere and each sphere's
// pairs (the rebuilds' steps that once ran on one thread while the others waited). Each thread
// counts a run of consecutive items per bucket, the buckets' starts are laid out bucket by bucket
// and, within a bucket, run by run, and each thread then places its run: the same order as one
// pass over the items, on any number of threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <omp.h>
#include <vector>

#include "dem/particles.hpp"  // parallel_threshold

namespace demscale::dem {

// Bucket b's items are order[start[b]] … order[start[b + 1] - 1].
struct Buckets {
    std::vector<std::uint32_t> start, order;
};

// key(e): item e's bucket, < buckets; called from several threads at once, once per item per pass
// (twice in all).
template <class Key>
Buckets bucket_by(std::size_t count, std::size_t buckets, Key key) {
    Buckets out{std::vector<std::uint32_t>(buckets + 1, 0), std::vector<std::uint32_t>(count)};
    // One run per thread, while the threads' counts (a bucket array each) stay within a few
    // times the items' own memory: a sparse grid is counted on fewer threads.
    const std::size_t most = std::max<std::size_t>(1, 16 * count / std::max<std::size_t>(buckets, 1));
    const int runs = static_cast<long>(count) > parallel_threshold ? static_cast<int>(std::min<std::size_t>(most, omp_get_max_threads())) : 1;
    std::vector<std::vector<std::uint32_t>> next(static_cast<std::size_t>(runs));  // per run: its next place per bucket
    std::vector<std::uint32_t> span_total(static_cast<std::size_t>(runs), 0);        // per span of buckets: its items
#pragma omp parallel num_threads(runs) if (runs > 1)
    {
        const auto c = static_cast<std::size_t>(omp_get_thread_num()), threads = static_cast<std::size_t>(omp_get_num_threads());
        std::vector<std::uint32_t>& mine = next[c];
        mine.assign(buckets, 0);
        const std::size_t from = count * c / threads, to = count * (c + 1) / threads;
        for (std::size_t e = from; e < to; ++e) ++mine[key(e)];
#pragma omp barrier
        // Thread c lays out the buckets of span c: first their total, then, once the spans before
        // it are added up, each bucket's start and each run's first place in it.
        const std::size_t b0 = buckets * c / threads, b1 = buckets * (c + 1) / threads;
        std::uint32_t total = 0;
        for (std::size_t b = b0; b < b1; ++b)
            for (std::size_t r = 0; r < threads; ++r) total += next[r][b];
        span_total[c] = total;
#pragma omp barrier
        std::uint32_t at = 0;
        for (std::size_t s = 0; s < c; ++s) at += span_total[s];
        for (std::size_t b = b0; b < b1; ++b) {
            out.start[b] = at;
            for (std::size_t r = 0; r < threads; ++r) std::swap(at, next[r][b]), at += next[r][b];
        }
#pragma omp barrier
        for (std::size_t e = from; e < to; ++e) out.order[mine[key(e)]++] = static_cast<std::uint32_t>(e);
    }
    out.start[buckets] = static_cast<std::uint32_t>(count);
    return out;
}

}  // namespace demscale::dem
