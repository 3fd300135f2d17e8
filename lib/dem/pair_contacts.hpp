// The particle pairs of the engine: the listed pairs in (i, j) order with their contact history,
// the merge of that history into each new neighbour list, and the forces of a step, gathered so
// that every particle sums its pairs in ascending pair order whatever the thread count.
// Threads (OpenMP, the engine's region): each thread takes the pairs of a slab of space and adds
// their forces at once to the spheres of its run that only it touches; the others gather theirs
// from a per-pair buffer (pair_shares.hpp). SI.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <omp.h>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/memory_use.hpp"
#include "dem/buckets.hpp"
#include "dem/checkpoint.hpp"
#include "dem/contact_geometry.hpp"
#include "dem/cross.hpp"
#include "dem/energy_ledger.hpp"
#include "dem/pair_shares.hpp"
#include "dem/particles.hpp"
#include "dem/work_split.hpp"

namespace demscale::dem {

template <class Law, bool Ledger>
class PairContacts {
public:
    using Lost = typename EnergyLedger<Ledger>::Lost;
    using LawState = typename Law::template StateFor<Lost>;  // a contact's history

    // The new list: the neighbour list's pairs (within the skin of touching: only those can touch
    // before the next rebuild), with the history of those already listed, plus every pair a liquid
    // bridge still holds, however far it has stretched. The list need not reach the rupture gap: a
    // bridge forms only at contact, and this keeps it until it ruptures. Both lists are sorted by
    // (i, j), so one merge pass does it, and the acting pairs keep their order (the same bits as a
    // list that reaches the rupture gap).
    // On all threads: each merges a run of the new list with the old pairs that fall among it,
    // first counting its pairs, then writing them where the runs before it end.
    void merge(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& near, const Particles& p, const Law& law) {
        std::vector<PairIndex> old;
        std::vector<LawState> old_states;
        std::vector<std::uint8_t> old_engaged;
        old.swap(pairs_), old_states.swap(states_), old_engaged.swap(engaged_);
        const auto listed = static_cast<long>(std::max(near.size(), old.size()));
        const std::size_t runs = listed > parallel_threshold ? static_cast<std::size_t>(omp_get_max_threads()) : 1;
        auto key = [](const PairIndex& q) { return std::make_pair(q.i, q.j); };
        // Run r: near[near_at[r], near_at[r + 1]) and the old pairs before near[near_at[r + 1]]
        // (all the rest for the last run), from the first not before near[near_at[r]].
        std::vector<std::size_t> near_at(runs + 1), old_at(runs + 1), out_at(runs + 1, 0);
        for (std::size_t r = 0; r <= runs; ++r) {
            near_at[r] = near.size() * r / runs;
            old_at[r] = r == 0 ? 0 : r == runs || near_at[r] == near.size() ? old.size()
                : static_cast<std::size_t>(std::lower_bound(old.begin(), old.end(), near[near_at[r]],
                                                            [&](const PairIndex& q, const auto& n) { return key(q) < n; }) - old.begin());
        }
        // Run r's merged pairs in order, each as emit(pair, its old index or none, engaged).
        constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
        auto walk = [&](std::size_t r, auto emit) {
            std::size_t k = old_at[r];
            auto keep_bridged = [&](std::size_t o) {
                if (law.acts_across_gap(old_states[o])) emit(old[o], o, std::uint8_t{1});
            };
            for (std::size_t m = near_at[r]; m < near_at[r + 1]; ++m) {
                const auto& [i, j] = near[m];
                for (; k < old_at[r + 1] && key(old[k]) < std::make_pair(i, j); ++k) keep_bridged(k);
                if (k < old_at[r + 1] && old[k].i == i && old[k].j == j) emit(old[k], k, old_engaged[k]), ++k;
                else emit(PairIndex{i, j}, none, std::uint8_t{0});
            }
            for (; k < old_at[r + 1]; ++k) keep_bridged(k);
        };
#pragma omp parallel for schedule(static, 1) if (runs > 1)
        for (long r = 0; r < static_cast<long>(runs); ++r)
            walk(static_cast<std::size_t>(r), [&](const PairIndex&, std::size_t, std::uint8_t) { ++out_at[static_cast<std::size_t>(r) + 1]; });
        for (std::size_t r = 0; r < runs; ++r) out_at[r + 1] += out_at[r];
        pairs_.resize(out_at[runs]), states_.resize(out_at[runs]), engaged_.resize(out_at[runs]);
#pragma omp parallel for schedule(static, 1) if (runs > 1)
        for (long r = 0; r < static_cast<long>(runs); ++r) {
            std::size_t at = out_at[static_cast<std::size_t>(r)];
            walk(static_cast<std::size_t>(r), [&](const PairIndex& q, std::size_t o, std::uint8_t engaged) {
                pairs_[at] = q, states_[at] = o == none ? LawState{} : old_states[o], engaged_[at] = engaged;
                ++at;
            });
        }
        index(p);
    }

    // After the engine reordered its spheres (sphere s is now new_index[s]): the same pairs, each
    // with its orientation and history, in ascending (i, j) order again, ready for merge().
    void renumber(const std::vector<std::uint32_t>& new_index) {
        for (auto& q : pairs_) q = {new_index[q.i], new_index[q.j]};
        std::vector<std::uint32_t> order(pairs_.size());
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return std::tie(pairs_[a].i, pairs_[a].j) < std::tie(pairs_[b].i, pairs_[b].j);
        });
        gather(pairs_, order), gather(states_, order), gather(engaged_, order);
    }

    // The forces of a step come in two stages, each run by the thread of a share (the engine's
    // step, simulation.hpp): first add_share_forces for every share, then, after a barrier,
    // gather_faces for every share. The pairs are cut into one share per thread the run was given
    // (share()), whatever number of threads runs the step (one thread may run them all when the
    // governor chose it, thread_governor.hpp): the ledger's sums, per share, stay the same bits.

    // Share `part`'s pairs, in pair order: each adds its force and torques at once to the spheres
    // only this share touches; the others' go to the buffer (a pair that does not act holds a zero
    // result there, listed_result: adding ±0 to a sum that starts at +0 or non-zero leaves it as
    // it was, so the gather needs no branch). `lost`: what the share's pairs dissipated. In blocks:
    // first the separations of the block's pairs that may act (separations), then their forces:
    // the square roots of a block do not wait on one another's forces, so the core overlaps them.
    void add_share_forces(int part, Particles& p, const Law& law, double dt, Lost& lost) {
        const double reach = law.range();
        std::array<Separation, separations_per_block> near;
        for (const auto& [first, end] : shares_.runs[static_cast<std::size_t>(part)])
            for (std::size_t from = first; from < end; from += separations_per_block)
                for (const Separation& at : separations(p, from, std::min(end, from + separations_per_block), near)) {
                    const std::size_t k = at.pair;
                    PairResult r;
                    const Acts acts = listed_result(p, law, dt, at, reach, lost, r);
                    if (acts == Acts::nothing) continue;
                    const PairIndex q = pairs_[k];
                    const std::uint8_t direct = shares_.direct[k];
                    if (direct & 1) {
                        p.force[q.i] += r.force_i;
                        if (acts == Acts::contact) p.torque[q.i] += r.torque_i;
                    }
                    if (direct & 2) {
                        p.force[q.j] -= r.force_i;
                        if (acts == Acts::contact) p.torque[q.j] += r.torque_j;
                    }
                    if (direct != PairShares::both_direct) results_[k] = r;
                }
    }

    // The spheres on a slab's face in share `part`'s run of spheres (sphere_shares), once every
    // share's pairs are done: each sums its pairs' results from the buffer in ascending pair order,
    // so every sphere gets its pairs in that order, after gravity, on any number of threads.
    void gather_faces(int part, Particles& p) const {
        for (const std::uint32_t i : faces_of(part)) {
            Vec3 f = p.force[i], t = p.torque[i];
            for (std::uint32_t e = incidence_start_[i]; e < incidence_start_[i + 1]; ++e) {
                const PairResult& r = results_[incidence_[e] / 2];
                const bool is_j = incidence_[e] % 2;
                f += (is_j ? -1.0 : 1.0) * r.force_i;  // x + (-1·y) is x − y, bit for bit
                t += is_j ? r.torque_j : r.torque_i;
            }
            p.force[i] = f;
            p.torque[i] = t;
        }
    }

    // The spheres of share `part`'s run that gather (gather_faces), ascending.
    std::span<const std::uint32_t> faces_of(int part) const {
        const auto& g = shares_.gathering;
        const auto from = std::lower_bound(g.begin(), g.end(), shares_.spheres[static_cast<std::size_t>(part)]);
        const auto to = std::lower_bound(from, g.end(), shares_.spheres[static_cast<std::size_t>(part) + 1]);
        return {from, to};
    }

    // How long share `part`'s thread took for its work before the barrier this step, s (the pair
    // loop and what the engine adds to it for the share's spheres): the next draw of the slabs
    // corrects its weights by these (share_work).
    void took(int part, double seconds) {
        costs_.took_step(static_cast<std::size_t>(part), seconds);
    }

    // Draws the threads' shares of the list (share_work) unless drawn for it already; returns their
    // number: one per thread the run was given (`given`), one for a short list. sphere_work(x):
    // what else the thread of sphere x's run does for it (its walls), in listed pairs' tests.
    template <class SphereWork = NoSphereWork>
    int share(const Particles& p, int given, SphereWork sphere_work = {}) {
        const int parts = static_cast<long>(pairs_.size()) <= parallel_threshold ? 1 : std::min(given, PairShares::most_threads);
        if (shares_.runs.size() != static_cast<std::size_t>(parts)) share_work(p, parts, sphere_work);
        return parts;
    }
    // Each share's run of spheres (PairShares::spheres), once share() drew them.
    const std::vector<std::size_t>& sphere_shares() const { return shares_.spheres; }

    // The axis the slabs cut from the next draw on (0 x, 1 y, 2 z; -1: the longest side of the
    // pairs' box): the one the engine's spatial sort lays its layers along.
    void cut_slabs_along(int axis) {
        if (axis != slab_axis_) slab_axis_ = axis, shares_ = {};
    }

    // Adds what the listed pairs hold now to e, J (in pair order).
    void add_stored_energy(StoredEnergy& e, const Particles& p, const Law& law, double dt) const {
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
            const std::size_t i = pairs_[k].i, j = pairs_[k].j;
            const Vec3 d = p.position[i] - p.position[j];
            const double dist = d.norm();
            if (dist - p.radius[i] - p.radius[j] > law.range()) continue;
            e += law.stored_energy(
                contact_geometry(law, p, dt, i, d, dist, p.velocity[j], p.angular_velocity[j], p.radius[j], shapes_[k], j), states_[k]);
        }
    }

    // The first of particle i's pairs (in pair order) whose contribution is not finite, described
    // ("from its contact with particle 7 (gap … m)"); evaluated again on a copy of its history.
    // name: each particle's name in the report (the engine's input order).
    std::optional<std::string> non_finite_contact(std::size_t i, const Particles& p, const Law& law, double dt,
                                                   const std::vector<std::uint32_t>& name) const {
        for (std::uint32_t e = incidence_start_[i]; e < incidence_start_[i + 1]; ++e) {
            const PairIndex q = pairs_[incidence_[e] / 2];
            LawState copy = states_[incidence_[e] / 2];
            Lost none;  // booked into nothing kept
            PairResult r;
            const Vec3 d = p.position[q.i] - p.position[q.j];
            pair_result(p, law, dt, q.i, q.j, d, d.norm(), shapes_[incidence_[e] / 2], copy, law.range(), none, r);
            if (r.force_i.allFinite() && r.torque_i.allFinite() && r.torque_j.allFinite()) continue;
            const std::size_t other = q.i == i ? q.j : q.i;
            const double gap = (p.position[i] - p.position[other]).norm() - p.radius[i] - p.radius[other];
            return ", from its contact with particle " + std::to_string(name[other]) + " (gap " + std::to_string(gap) + " m)";
        }
        return std::nullopt;
    }

    // Checkpoint: the pairs with their history. The engaged flags are not recorded: after a
    // restore the first step evaluates every pair, as they may hold history.
    void write(CheckpointWriter& w) const {
        std::vector<ListedPair> listed(pairs_.size());
        for (std::size_t k = 0; k < pairs_.size(); ++k) listed[k] = {pairs_[k].i, pairs_[k].j, states_[k]};
        w.array(listed);
    }
    // Returns the listed (i, j), for the neighbour list's own record.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> read(CheckpointReader& r, const Particles& p) {
        std::vector<ListedPair> records;
        r.array(records);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> listed;
        pairs_.clear(), states_.clear();
        for (const auto& q : records) listed.emplace_back(q.i, q.j), pairs_.push_back({q.i, q.j}), states_.push_back(q.state);
        engaged_.assign(pairs_.size(), 1);
        index(p);
        return listed;
    }

    std::size_t size() const { return pairs_.size(); }

    // What the pairs hold, by consumer (bytes).
    void add_memory(std::vector<MemoryItem>& out) const {
        out.push_back({"pair list (i, j)", capacity_bytes(pairs_)});
        out.push_back({"pair histories", capacity_bytes(states_) + capacity_bytes(engaged_)});
        out.push_back({"pair shapes (R*, m*, ...)", capacity_bytes(shapes_)});
        out.push_back({"pair results (force, torques)", capacity_bytes(results_)});
        out.push_back({"pair incidence and shares", capacity_bytes(incidence_start_) + capacity_bytes(incidence_) + capacity_bytes(shares_.runs) +
                                                         capacity_bytes(shares_.direct) + capacity_bytes(shares_.gathering) + capacity_bytes(shares_.spheres)});
    }

private:
    static_assert(std::is_standard_layout_v<LawState>);  // written as bytes

    struct PairIndex {
        std::uint32_t i, j;  // oriented by the engine's input order (NeighborList::build's rank)
    };
    struct ListedPair {  // a checkpoint's record of one listed pair
        std::uint32_t i, j;
        LawState state;
    };
    struct PairResult {  // what one pair contributes this step
        Vec3 force_i = Vec3::Zero(), torque_i = Vec3::Zero(), torque_j = Vec3::Zero();
    };

    // For each particle, the pairs it belongs to in ascending pair order (CSR), with its side:
    // entry = 2·pair + (0 if it is i, 1 if it is j); and each pair's shape.
    void index(const Particles& p) {
        Buckets by_sphere = bucket_by(2 * pairs_.size(), p.size(), [&](std::size_t e) { return e % 2 ? pairs_[e / 2].j : pairs_[e / 2].i; });
        incidence_start_.swap(by_sphere.start), incidence_.swap(by_sphere.order);
        shapes_.resize(pairs_.size());
        const long listed = static_cast<long>(pairs_.size());
#pragma omp parallel for schedule(static) if (listed > parallel_threshold)  // two roots and four divisions a pair
        for (long k = 0; k < listed; ++k) shapes_[k] = pair_shape(p, pairs_[k].i, pairs_[k].j);
        shares_ = {};  // drawn again for the new list (share_work)
    }

    // What a listed pair contributes: nothing (beyond the law's reach, or apart with no bridge
    // holding it), a central force only (a bridge across a gap), or a contact's force and torques.
    enum class Acts { nothing, central, contact };

    // What listed pair (i, j) of that shape, with history s, contributes now, into out (left zero
    // where it does not act; a central force leaves the torques zero), its centres d = x_i − x_j
    // apart, dist = |d|. A pair that stops acting has its springs released.
    template <class L>
    DEMSCALE_HOT static Acts pair_result(const Particles& p, const Law& law, double dt, std::size_t i, std::size_t j, const Vec3& d,
                                         double dist, const PairShape& shape, LawState& s, double reach, L& lost, PairResult& out) {
        const double gap = dist - p.radius[i] - p.radius[j];
        if (gap > reach || (gap > 0 && !law.acts_across_gap(s))) {
            law.release(s, lost);
            return Acts::nothing;
        }
        // A bridge across a gap pulls along the line of centres: no contact geometry needed. The
        // overlap and the force are computed as contact_geometry and force() compute them (same
        // bits). A viscous bridge also drags across the gap: the full geometry below.
        if (const double overlap = p.radius[i] + p.radius[j] - dist; gap > 0 && overlap <= 0 && !law.needs_gap_velocity()) {
            out.force_i = (0.0 - law.pull_apart(overlap, harmonic_radius(p.radius[i], p.radius[j], shape), 0.0, dt, false, s, lost)) *
                          (d * (1.0 / dist));
            return Acts::central;
        }
        const ContactPair c = contact_geometry(law, p, dt, i, d, dist, p.velocity[j], p.angular_velocity[j], p.radius[j], shape, j);
        const ContactForce f = law.force(c, s, lost);
        out.force_i = f.on_i;
        if (c.overlap <= 0 && !law.needs_gap_velocity()) return Acts::central;  // gap rounded to 0: the same central pull
        const double li = p.radius[i] - 0.5 * c.overlap, lj = p.radius[j] - 0.5 * c.overlap;
        out.torque_i = cross(-li * c.normal, f.tangential) + f.rolling_torque;
        out.torque_j = cross(lj * c.normal, -f.tangential) - f.rolling_torque;
        return Acts::contact;
    }

    // Which thread takes which pairs (pair_shares.hpp), drawn when the list changes (or the thread
    // count does), not every step: the acting pairs change little between rebuilds. Without the
    // ledger, slabs of about equal work, a pair that acted last step weighing acting_cost pairs
    // passed over (a pile's bottom pairs press, its flying top's are apart: equal counts of pairs
    // left one thread waiting at 0.09 ms of a 0.2 ms loop, docs/performance.md). With the ledger,
    // runs of equal counts of consecutive pairs: its sums are per share and must not depend on
    // the positions at the draw or the engaged flags, which a checkpoint does not carry.
    template <class SphereWork>
    void share_work(const Particles& p, int parts, SphereWork sphere_work) {
        if constexpr (Ledger) {
            std::vector<std::size_t> split;
            split_by_work(split, pairs_.size(), parts, 0, [](std::size_t) { return std::size_t{0}; });
            shares_ = shares_of(pairs_, p.size(), parts, [&](std::size_t k) {  // the run k lies in
                return static_cast<std::size_t>(std::upper_bound(split.begin(), split.end(), k) - split.begin()) - 1;
            });
        } else {
            const auto owner =
                slab_owner(pairs_, p, parts, slab_axis_, [&](std::size_t k) { return 1 + acting_cost * engaged_[k]; }, sphere_work, &costs_);
            shares_ = shares_of(pairs_, p.size(), parts, [&](std::size_t k) { return owner[k]; });
        }
        results_.assign(pairs_.size(), PairResult{});  // the spheres that gather changed: zero where a pair does not act
    }

    // A listed pair that may act this step, with its centres' separation d = x_i − x_j (m) and
    // dist = |d| (m).
    struct Separation {
        std::uint32_t pair;
        double dist;
        Vec3 d;
    };
    static constexpr std::size_t separations_per_block = 32;

    // The separations of listed pairs [from, to) that may act, in the first entries of `near`, in
    // pair order. A pair without history (engaged_[k] = 0: its state is zero) that is surely apart
    // is left out: it would do nothing and keep its zero state, so it needs no square root and no
    // access to its state. The margin on the squared distance (1e-12 relative) is far above
    // rounding: the decision is pair_result's own.
    std::span<const Separation> separations(const Particles& p, std::size_t from, std::size_t to,
                                            std::array<Separation, separations_per_block>& near) const {
        std::size_t n = 0;
        for (std::size_t k = from; k < to; ++k) {
            const std::size_t i = pairs_[k].i, j = pairs_[k].j;
            const Vec3 d = p.position[i] - p.position[j];
            const double d2 = d.squaredNorm(), touch = p.radius[i] + p.radius[j];
            if (!engaged_[k] && d2 > touch * touch * (1 + 1e-12)) continue;
            near[n++] = {static_cast<std::uint32_t>(k), std::sqrt(d2), d};  // sqrt(d2) is d.norm(), bit for bit
        }
        return {near.data(), n};
    }

    // pair_result for the listed pair at separation `at` (separations), with its contact history.
    template <class L>
    DEMSCALE_HOT Acts listed_result(const Particles& p, const Law& law, double dt, const Separation& at, double reach, L& lost,
                                    PairResult& out) {
        const std::size_t k = at.pair, i = pairs_[k].i, j = pairs_[k].j;
        const Acts acts = pair_result(p, law, dt, i, j, at.d, at.dist, shapes_[k], states_[k], reach, lost, out);
        if (acts == Acts::nothing) results_[k] = PairResult{};  // released: its result zero again, as its state
        engaged_[k] = acts != Acts::nothing;
        return acts;
    }

    // The listed pairs in (i, j) order, each with its contact history and whether that history may
    // be non-zero (0: surely zero). Apart, three arrays: the pair loop reads a pair's history only
    // when it may act.
    std::vector<PairIndex> pairs_;
    std::vector<LawState> states_;
    std::vector<std::uint8_t> engaged_;
    std::vector<PairShape> shapes_;
    std::vector<PairResult> results_;
    PairShares shares_;    // which thread takes which pairs (share_work)
    int slab_axis_ = -1;  // the axis the slabs cut (cut_slabs_along)
    SlabCosts costs_;     // the last draw's slabs and their threads' seconds (took)
    std::vector<std::uint32_t> incidence_start_, incidence_;
};

}  // namespace demscale::dem
