#include "dem/neighbor_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "dem/buckets.hpp"

namespace demscale::dem {

void NeighborList::build(const Particles& p, const std::vector<std::uint32_t>* rank) {
    pairs_.clear();
    built_at_ = p.position;
    ++builds_;
    const std::size_t n = p.size();
    if (n < 2) return;
    const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
    const double cell = 2.0 * r_max + skin_;
    Vec3 lo = p.position[0], hi = p.position[0];
    for (const auto& x : p.position) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    std::array<long, 3> dims{};
    for (int k = 0; k < 3; ++k) dims[k] = std::max(1L, static_cast<long>(std::floor((hi[k] - lo[k]) / cell)) + 1);
    if (static_cast<double>(dims[0]) * static_cast<double>(dims[1]) * static_cast<double>(dims[2]) > 1e8)
        throw std::runtime_error("neighbour grid too large: particles spread over " + std::to_string(dims[0]) + " x " +
                                 std::to_string(dims[1]) + " x " + std::to_string(dims[2]) + " cells");
    auto cell_of = [&](const Vec3& x, int k) { return std::min(dims[k] - 1, static_cast<long>((x[k] - lo[k]) / cell)); };
    // The particles sorted into cells.
    std::vector<std::size_t> index(n);
    const long count = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (count > parallel_threshold)
    for (long ii = 0; ii < count; ++ii) {
        const auto& x = p.position[static_cast<std::size_t>(ii)];
        index[static_cast<std::size_t>(ii)] = static_cast<std::size_t>((cell_of(x, 2) * dims[1] + cell_of(x, 1)) * dims[0] + cell_of(x, 0));
    }
    const auto [start, order] = bucket_by(n, static_cast<std::size_t>(dims[0] * dims[1] * dims[2]), [&](std::size_t i) { return index[i]; });

    // Each pair once: sphere i takes the spheres after it in its own cell and every sphere in the
    // 13 cells "after" its cell (half of the 26 around it), so no pair is tested twice; the sort
    // below gives the same list as testing all 27 cells.
    static constexpr std::array<std::array<long, 3>, 13> after{{{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0},  {-1, -1, 1},
                                                                {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1},  {1, 0, 1},
                                                                {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}}};
    const double gap = skin_;
#pragma omp parallel
    {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> local;
        auto test = [&](std::uint32_t a, std::uint32_t b) {
            if (p.fixed[a] && p.fixed[b]) return;  // two fixed grains never interact
            const double reach = p.radius[a] + p.radius[b] + gap;
            if ((p.position[b] - p.position[a]).squaredNorm() >= reach * reach) return;
            if (a > b) std::swap(a, b);
            if (rank && (*rank)[a] > (*rank)[b]) std::swap(a, b);
            local.emplace_back(a, b);
        };
#pragma omp for schedule(static) nowait
        for (long ii = 0; ii < count; ++ii) {
            const auto i = static_cast<std::uint32_t>(ii);
            const auto& x = p.position[i];
            const long cx = cell_of(x, 0), cy = cell_of(x, 1), cz = cell_of(x, 2);
            const std::size_t own = index[i];
            for (std::uint32_t k = start[own]; k < start[own + 1]; ++k)
                if (order[k] > i) test(i, order[k]);
            for (const auto& [dx, dy, dz] : after) {
                const long X = cx + dx, Y = cy + dy, Z = cz + dz;
                if (X < 0 || Y < 0 || Z < 0 || X >= dims[0] || Y >= dims[1] || Z >= dims[2]) continue;
                const std::size_t c = static_cast<std::size_t>((Z * dims[1] + Y) * dims[0] + X);
                for (std::uint32_t k = start[c]; k < start[c + 1]; ++k) test(i, order[k]);
            }
        }
#pragma omp critical
        pairs_.insert(pairs_.end(), local.begin(), local.end());
    }
    // Ascending (i, j), a fixed order whatever the thread count: bucketed by i, then each sphere's
    // few j sorted (a comparison sort of the whole list took a quarter of the build).
    const Buckets by_first = bucket_by(pairs_.size(), n, [&](std::size_t k) { return pairs_[k].first; });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> sorted(pairs_.size());
    // Each sphere's pairs gathered and sorted apart from the others', on all threads.
#pragma omp parallel for schedule(static) if (count > parallel_threshold)
    for (long ii = 0; ii < count; ++ii) {
        const auto i = static_cast<std::size_t>(ii);
        for (std::uint32_t k = by_first.start[i]; k < by_first.start[i + 1]; ++k) sorted[k] = pairs_[by_first.order[k]];
        std::sort(sorted.begin() + by_first.start[i], sorted.begin() + by_first.start[i + 1]);
    }
    pairs_.swap(sorted);
}

// A pair left out of the list was at least `skin` apart at the build; it can touch only once its
// two spheres have moved more than `skin` between them. The two largest displacements bound that
// for every pair: a tighter test than "any sphere moved skin/2" when one sphere outruns the rest.
bool NeighborList::needs_rebuild(const Particles& p) const {
    if (!built_for(p)) return true;
    Shifts all;
    const long n = static_cast<long>(p.size());
    // Each thread's two largest, then the largest two of those: the same two values in any order.
#pragma omp parallel if (n > parallel_threshold)
    {
        Shifts mine;
#pragma omp for schedule(static) nowait
        for (long i = 0; i < n; ++i) mine.keep(squared_shift(p, static_cast<std::size_t>(i)));
#pragma omp critical
        all += mine;
    }
    return needs_rebuild(all);
}

bool NeighborList::needs_rebuild(const Shifts& all) const {
    // The margin keeps rounding on the safe side.
    return std::sqrt(all.top) + std::sqrt(all.next) > skin_ * (1.0 - 1e-9);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const Particles& p, double gap) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t j = i + 1; j < p.size(); ++j) {
            if (p.fixed[i] && p.fixed[j]) continue;
            const double reach = p.radius[i] + p.radius[j] + gap;
            if ((p.position[j] - p.position[i]).squaredNorm() < reach * reach) out.emplace_back(i, j);
        }
    return out;
}

}  // namespace demscale::dem
