// Which thread evaluates which listed pair, and where its force goes. Each thread takes the pairs
// of one slab of space (by the position of each pair's first sphere, along the scene's longest
// side, slabs of about equal work), in ascending pair order. Each thread also has a run of
// spheres, those whose first pair it takes (with the spheres sorted in layers across the slabs'
// axis, spatial_order.hpp, a run is nearly the thread's slab): the engine's step gives it their
// gravity, walls, checks and kicks, so a sphere's state stays in one core's cache through the
// step. A sphere of a thread's run whose pairs all fall to that thread gets its forces added at
// once, in pair order; the others (near a slab's face, whose pairs fall to two threads, or the
// few placed in another thread's run) gather their pairs' results from a buffer after the loop,
// by their run's thread: no thread writes to another's run before the barrier. Both keep each
// sphere's sum in ascending pair order: the same bits for any split and any thread count.
// Splitting the list into runs of consecutive pairs instead leaves most spheres on a face unless
// the spheres are ordered in space (docs/dem-engine.md).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <omp.h>
#include <utility>
#include <vector>

#include "dem/particles.hpp"
#include "dem/slab_costs.hpp"

namespace demscale::dem {

struct PairShares {
    using Run = std::pair<std::size_t, std::size_t>;  // pairs [first, second)
    std::vector<std::vector<Run>> runs;                // per share (thread), ascending
    std::vector<std::uint8_t> direct;                  // per pair: bit 0 adds to i at once, bit 1 to j
    std::vector<std::uint32_t> gathering;              // spheres that gather, ascending (above)
    // Share t's spheres for the passes over them: [spheres[t], spheres[t + 1]), as many as have
    // their first pair (in pair order) in share t; a sphere without pairs goes with the one before.
    std::vector<std::size_t> spheres;
    static constexpr std::uint8_t both_direct = 3;
    static constexpr int most_threads = 253;  // a sphere's thread is one byte, with two marks
};

// The shares for `parts` threads when pair k falls to thread owner(k); pairs (with members i, j)
// ascending, n spheres; parts ≤ most_threads. owner is called from several threads at once. The
// pairs' passes run on all threads: each takes a run of consecutive pairs and notes, per sphere,
// the thread of its first pair there and whether its pairs there all have one thread; the notes
// are then joined sphere by sphere in run order (the same as one pass in pair order).
template <class Pairs, class Owner>
PairShares shares_of(const Pairs& pairs, std::size_t n, int parts, Owner owner) {
    PairShares s;
    s.runs.assign(static_cast<std::size_t>(parts), {});
    const long listed = static_cast<long>(pairs.size());
    s.direct.resize(pairs.size());
    std::vector<std::uint8_t> thread_of_pair(pairs.size());
#pragma omp parallel for schedule(static) if (listed > parallel_threshold)
    for (long k = 0; k < listed; ++k) thread_of_pair[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(owner(static_cast<std::size_t>(k)));
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        auto& runs = s.runs[thread_of_pair[k]];
        if (!runs.empty() && runs.back().second == k) ++runs.back().second;
        else runs.emplace_back(k, k + 1);
    }
    constexpr std::uint8_t none = 0xFF, mixed = 0xFE;  // a sphere's thread: none yet, or two
    auto join = [](std::uint8_t a, std::uint8_t b) -> std::uint8_t { return a == none || a == b ? b : b == none ? a : mixed; };
    std::vector<std::uint8_t> thread_of(n, none), first_of(n, none);
    std::vector<std::vector<std::uint8_t>> notes;  // per run of pairs: thread_of, then first_of, 2n bytes
#pragma omp parallel if (listed > parallel_threshold)
    {
        const int c = omp_get_thread_num(), chunks = omp_get_num_threads();
#pragma omp single
        notes.assign(static_cast<std::size_t>(chunks), std::vector<std::uint8_t>(2 * n, none));  // implied barrier after
        std::uint8_t* const mine = notes[static_cast<std::size_t>(c)].data();
        const std::size_t from = pairs.size() * static_cast<std::size_t>(c) / static_cast<std::size_t>(chunks);
        const std::size_t to = pairs.size() * static_cast<std::size_t>(c + 1) / static_cast<std::size_t>(chunks);
        for (std::size_t k = from; k < to; ++k)
            for (const std::uint32_t x : {pairs[k].i, pairs[k].j}) {
                mine[x] = join(mine[x], thread_of_pair[k]);
                if (mine[n + x] == none) mine[n + x] = thread_of_pair[k];
            }
#pragma omp barrier
#pragma omp for schedule(static)
        for (long xx = 0; xx < static_cast<long>(n); ++xx) {
            const auto x = static_cast<std::size_t>(xx);
            for (const auto& note : notes) {
                thread_of[x] = join(thread_of[x], note[x]);
                if (first_of[x] == none) first_of[x] = note[n + x];
            }
        }
    }
    s.spheres.assign(static_cast<std::size_t>(parts) + 1, 0);
    std::uint8_t before = 0;
    for (const std::uint8_t t : first_of) before = t == none ? before : t, ++s.spheres[before + 1u];
    for (int t = 0; t < parts; ++t) s.spheres[t + 1u] += s.spheres[t];
    // A sphere whose pairs all fall to a thread other than its run's (one placed out of its slab
    // by the order) gathers too: a thread then writes at once only to the spheres of its run.
    for (std::size_t t = 0; t < static_cast<std::size_t>(parts); ++t)
        for (std::size_t x = s.spheres[t]; x < s.spheres[t + 1]; ++x)
            if (thread_of[x] != none && thread_of[x] != t) thread_of[x] = mixed;
#pragma omp parallel for schedule(static) if (listed > parallel_threshold)
    for (long kk = 0; kk < listed; ++kk) {
        const auto k = static_cast<std::size_t>(kk);
        s.direct[k] = static_cast<std::uint8_t>((thread_of[pairs[k].i] != mixed) | (thread_of[pairs[k].j] != mixed) << 1);
    }
    for (std::uint32_t x = 0; x < n; ++x)
        if (thread_of[x] == mixed) s.gathering.push_back(x);
    return s;
}

// No work at the spheres themselves (slab_owner's default).
struct NoSphereWork {
    std::size_t operator()(std::size_t) const { return 0; }
};

// Pair k's thread by slabs of space: each pair weighs weight(k) and lies where its first sphere
// does, and sphere x adds sphere_work(x) where it lies (its walls, which the thread of its run
// takes, simulation.hpp); the slabs cut `axis` (0 x, 1 y, 2 z; -1: the longest side of the box
// around the pairs' first spheres) into `parts` of about equal weight, at a resolution of 1/1024
// of the box's side. costs (optional): the last draw's slabs with their measured seconds, which
// correct the weights (SlabCosts::factors); replaced by this draw's slabs, their seconds zero.
template <class Pairs, class Weight, class SphereWork = NoSphereWork>
std::vector<std::uint8_t> slab_owner(const Pairs& pairs, const Particles& p, int parts, int axis, Weight weight,
                                     SphereWork sphere_work = {}, SlabCosts* costs = nullptr) {
    std::vector<std::uint8_t> owner(pairs.size(), 0);
    if (parts < 2 || pairs.empty()) return owner;
    Vec3 lo = p.position[pairs[0].i], hi = lo;
    for (const auto& q : pairs) lo = lo.cwiseMin(p.position[q.i]), hi = hi.cwiseMax(p.position[q.i]);
    if (axis < 0 || axis > 2) (hi - lo).maxCoeff(&axis);
    constexpr std::size_t bins = 1024;
    const double per_bin = bins / std::max(hi[axis] - lo[axis], 1e-300);
    auto bin_at = [&](const Vec3& x) {
        return std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, (x[axis] - lo[axis]) * per_bin)));
    };
    auto bin_of = [&](std::size_t k) { return bin_at(p.position[pairs[k].i]); };
    // Modelled weight per bin: whole numbers, so that the threads' partial sums add up exactly.
    std::vector<double> load(bins, 0);
    const long listed = static_cast<long>(pairs.size()), n = static_cast<long>(p.size());
#pragma omp parallel if (listed > parallel_threshold)
    {
        std::vector<double> mine(bins, 0);
#pragma omp for schedule(static) nowait
        for (long k = 0; k < listed; ++k) mine[bin_of(static_cast<std::size_t>(k))] += static_cast<double>(weight(static_cast<std::size_t>(k)));
#pragma omp for schedule(static) nowait
        for (long x = 0; x < n; ++x)
            if (const std::size_t w = sphere_work(static_cast<std::size_t>(x))) mine[bin_at(p.position[static_cast<std::size_t>(x)])] += static_cast<double>(w);
#pragma omp critical
        for (std::size_t b = 0; b < bins; ++b) load[b] += mine[b];
    }
    auto edge = [&](std::size_t b) { return lo[axis] + static_cast<double>(b) / per_bin; };  // m, a bin's low side
    std::vector<double> cost(load);  // corrected by the last draw's measurement
    const std::vector<double> factor = costs ? costs->factors(parts, axis) : std::vector<double>{};
    double total = 0;
    for (std::size_t b = 0; b < bins; ++b) {
        if (!factor.empty()) cost[b] *= factor[costs->slab_at(edge(b) + 0.5 / per_bin)];
        total += cost[b];
    }
    // A bin goes to the slab its middle falls in, by the cost before it.
    std::vector<std::uint8_t> slab(bins);
    double before = 0;
    for (std::size_t b = 0; b < bins; ++b) {
        const double middle = before + 0.5 * cost[b];
        slab[b] = static_cast<std::uint8_t>(std::min(parts - 1, static_cast<int>(middle * parts / std::max(total, 1e-300))));
        before += cost[b];
    }
#pragma omp parallel for schedule(static) if (listed > parallel_threshold)
    for (long k = 0; k < listed; ++k) owner[static_cast<std::size_t>(k)] = slab[bin_of(static_cast<std::size_t>(k))];
    if (costs) {
        *costs = SlabCosts{axis, {}, std::vector<double>(static_cast<std::size_t>(parts), 0.0), std::vector<std::vector<double>>(static_cast<std::size_t>(parts))};
        for (std::size_t b = 0; b < bins; ++b) {
            costs->weight[slab[b]] += load[b];
            if (costs->cuts.size() < slab[b]) costs->cuts.resize(slab[b], edge(b));  // an empty slab's cuts coincide
        }
        costs->cuts.resize(static_cast<std::size_t>(parts) - 1, std::numeric_limits<double>::infinity());  // slabs no bin reached
    }
    return owner;
}

}  // namespace demscale::dem
