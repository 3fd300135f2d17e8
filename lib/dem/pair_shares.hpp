// Which thread evaluates which listed pair, and where its force goes. Each thread takes the pairs
// of one slab of space (by the position of each pair's first sphere, along the scene's longest
// side, slabs of about equal work), in ascending pair order. A sphere whose pairs all fall to one
// thread gets its forces added at once by that thread, in pair order; only the spheres near a
// slab's face, whose pairs fall to two threads, gather their pairs' results from a buffer after
// the loop. Both keep each sphere's sum in ascending pair order: the same bits for any split and
// any thread count. Splitting the list into runs of consecutive pairs instead leaves most spheres
// on a face unless the spheres are ordered in space (docs/dem-engine.md). The engine's passes over
// the spheres (kicks, drift, walls) give each thread a run of spheres too, those whose first pair
// it takes: with the spheres sorted in layers across the slabs' axis (spatial_order.hpp) a run is
// nearly the thread's slab, and a sphere's state stays in one core's cache through the step.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "dem/particles.hpp"

namespace demscale::dem {

struct PairShares {
    using Run = std::pair<std::size_t, std::size_t>;  // pairs [first, second)
    std::vector<std::vector<Run>> runs;                // per share (thread), ascending
    std::vector<std::uint8_t> direct;                  // per pair: bit 0 adds to i at once, bit 1 to j
    std::vector<std::uint32_t> gathering;              // spheres with pairs of two threads
    // Share t's spheres for the passes over them: [spheres[t], spheres[t + 1]), as many as have
    // their first pair (in pair order) in share t; a sphere without pairs goes with the one before.
    std::vector<std::size_t> spheres;
    static constexpr std::uint8_t both_direct = 3;
    static constexpr int most_threads = 253;  // a sphere's thread is one byte, with two marks
};

// The shares for `parts` threads when pair k falls to thread owner(k); pairs (with members i, j)
// ascending, n spheres; parts ≤ most_threads.
template <class Pairs, class Owner>
PairShares shares_of(const Pairs& pairs, std::size_t n, int parts, Owner owner) {
    PairShares s;
    s.runs.assign(static_cast<std::size_t>(parts), {});
    s.direct.resize(pairs.size());
    constexpr std::uint8_t none = 0xFF, mixed = 0xFE;  // a sphere's thread: none yet, or two
    std::vector<std::uint8_t> thread_of(n, none), first_of(n, none);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const auto t = static_cast<std::uint8_t>(owner(k));
        auto& runs = s.runs[t];
        if (!runs.empty() && runs.back().second == k) ++runs.back().second;
        else runs.emplace_back(k, k + 1);
        for (const std::uint32_t x : {pairs[k].i, pairs[k].j}) {
            thread_of[x] = thread_of[x] == none || thread_of[x] == t ? t : mixed;
            if (first_of[x] == none) first_of[x] = t;
        }
    }
    s.spheres.assign(static_cast<std::size_t>(parts) + 1, 0);
    std::uint8_t before = 0;
    for (const std::uint8_t t : first_of) before = t == none ? before : t, ++s.spheres[before + 1u];
    for (int t = 0; t < parts; ++t) s.spheres[t + 1u] += s.spheres[t];
    for (std::size_t k = 0; k < pairs.size(); ++k)
        s.direct[k] = static_cast<std::uint8_t>((thread_of[pairs[k].i] != mixed) | (thread_of[pairs[k].j] != mixed) << 1);
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
// of the box's side.
template <class Pairs, class Weight, class SphereWork = NoSphereWork>
std::vector<std::uint8_t> slab_owner(const Pairs& pairs, const Particles& p, int parts, int axis, Weight weight,
                                     SphereWork sphere_work = {}) {
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
    std::vector<std::size_t> load(bins, 0);
    std::size_t total = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::size_t w = weight(k);
        load[bin_of(k)] += w, total += w;
    }
    for (std::size_t x = 0; x < p.size(); ++x)
        if (const std::size_t w = sphere_work(x)) load[bin_at(p.position[x])] += w, total += w;
    // A bin goes to the slab its middle falls in, by the weight before it.
    std::vector<std::uint8_t> slab(bins);
    std::size_t before = 0;
    for (std::size_t b = 0; b < bins; ++b) {
        const std::size_t middle = 2 * before + load[b];  // twice the weight up to the bin's middle
        slab[b] = static_cast<std::uint8_t>(std::min<std::size_t>(parts - 1, middle * parts / (2 * std::max<std::size_t>(total, 1))));
        before += load[b];
    }
    for (std::size_t k = 0; k < pairs.size(); ++k) owner[k] = slab[bin_of(k)];
    return owner;
}

}  // namespace demscale::dem
