// The DEM engine for one contact law: particles, walls, gravity, velocity-Verlet integration
// (translation and rotation), a Verlet neighbour list with contact history carried across rebuilds,
// and energy bookkeeping. SI units.
// Threads (OpenMP): pair forces are computed in parallel into a per-pair buffer, then each particle
// sums its contributions in a fixed pair order (on one thread each pair adds to its particles
// directly, in that same order), so trajectories are bit-identical for any thread count (the energy ledger's sums, per thread, only for the same thread count).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <istream>
#include <omp.h>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <type_traits>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "dem/contact_law.hpp"
#include "dem/energy.hpp"
#include "dem/neighbor_list.hpp"
#include "dem/walls.hpp"

namespace demscale::dem {

// Ledger: book every loss and the walls' work (energy() then balances), or not (about 10 % faster;
// energy() then reports kinetic, gravitational and stored energy only).
template <class Law, bool Ledger = true>
class Simulation {
    using Lost = std::conditional_t<Ledger, Dissipation, NoDissipation>;  // what the laws book into
    using LawState = typename Law::template StateFor<Lost>;              // a contact's history

public:
    Simulation(Particles particles, Law law, std::vector<Wall> walls, Vec3 gravity, double dt, double skin)
        : p_(std::move(particles)), law_(std::move(law)), walls_(std::move(walls)), gravity_(gravity), dt_(dt),
          neighbors_(skin) {
        require_positive(dt, "dt");
        require_positive(skin, "skin");
        wall_state_.assign(walls_.size(), std::vector<LawState>(p_.size()));
        wall_engaged_.assign(walls_.size(), std::vector<std::uint8_t>(p_.size(), 0));
        index_particles();
        rebuild();
        compute_forces();
    }

    // One velocity-Verlet step: half kick, drift, forces, half kick.
    void step() {
        half_kick();
        double probe = 0;  // NaN or inf anywhere makes the sum non-finite: one check per step
        for (std::size_t i = 0; i < p_.size(); ++i) p_.position[i] += dt_ * p_.velocity[i], probe += p_.position[i].sum();
        if (!std::isfinite(probe))
            for (std::size_t i = 0; i < p_.size(); ++i)
                if (!p_.position[i].allFinite()) throw std::runtime_error(non_finite_report(i, "position of"));
        if (neighbors_.needs_rebuild(p_)) rebuild();
        compute_forces();
        half_kick();
        time_ += dt_;
        ++steps_;
    }

    const Particles& particles() const { return p_; }
    Particles& particles() { return p_; }  // to move particles or set velocities; masses stay as built
    std::vector<Wall>& walls() { return walls_; }  // e.g. to schedule the cone's lift

    // Takes a wall out of the scene (the slump cone after its lift), with its contact history.
    // The energy its contacts held leaves with it (booked as work the wall took away).
    void remove_wall(std::size_t index) {
        if constexpr (Ledger)
            for (std::size_t i = 0; i < p_.size(); ++i)
                if (const auto c = wall_contact(walls_[index], i)) wall_work_ -= law_.stored_energy(*c, wall_state_[index][i]).total();
        walls_.erase(walls_.begin() + static_cast<long>(index));
        wall_state_.erase(wall_state_.begin() + static_cast<long>(index));
        wall_engaged_.erase(wall_engaged_.begin() + static_cast<long>(index));
    }

    // Forces for the current state after particles were moved by hand (tests, prescribed motion).
    void refresh_forces() {
        if (neighbors_.needs_rebuild(p_)) rebuild();
        compute_forces();
    }
    const NeighborList& neighbors() const { return neighbors_; }
    double time() const { return time_; }
    std::size_t steps() const { return steps_; }
    double dt() const { return dt_; }

    // The energy ledger now. Stored energies are summed here, on demand, not in every step.
    Energy energy() const {
        Energy e;
        e.dissipated = dissipated_;
        e.wall_work = wall_work_;
        for (std::size_t i = 0; i < p_.size(); ++i) {
            if (p_.fixed[i]) continue;  // no motion, constant height
            e.kinetic += 0.5 * p_.mass[i] * p_.velocity[i].squaredNorm() +
                         0.5 * p_.inertia[i] * p_.angular_velocity[i].squaredNorm();
            e.gravitational -= p_.mass[i] * gravity_.dot(p_.position[i]);
        }
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
            const std::size_t i = pairs_[k].i, j = pairs_[k].j;
            const Vec3 d = p_.position[i] - p_.position[j];
            const double dist = d.norm();
            if (dist - p_.radius[i] - p_.radius[j] > law_.range()) continue;
            e.stored += law_.stored_energy(
                pair_geometry(i, d, dist, p_.velocity[j], p_.angular_velocity[j], p_.radius[j], shapes_[k], j), states_[k]);
        }
        for (std::size_t w = 0; w < walls_.size(); ++w)
            for (std::size_t i = 0; i < p_.size(); ++i)
                if (const auto c = wall_contact(walls_[w], i)) e.stored += law_.stored_energy(*c, wall_state_[w][i]);
        return e;
    }

    // Checkpoint: everything the next step depends on (particles with their current forces, time,
    // energies, the neighbour list's reference positions and pairs with contact history, wall
    // contact history), so that a restart continues bit for bit. Walls and the law come from the scene.
    void save(std::ostream& out) const {
        auto raw = [&](const void* data, std::size_t bytes) { out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes)); };
        auto vec = [&](const auto& v) {
            const std::uint64_t n = v.size();
            raw(&n, sizeof n);
            raw(v.data(), n * sizeof(v[0]));
        };
        raw(checkpoint_magic, sizeof checkpoint_magic);
        const std::uint8_t ledger = Ledger;  // the histories' layout depends on it
        raw(&ledger, sizeof ledger);
        vec(p_.position), vec(p_.velocity), vec(p_.angular_velocity), vec(p_.force), vec(p_.torque);
        vec(p_.radius), vec(p_.mass), vec(p_.inertia), vec(p_.species), vec(p_.fixed);
        raw(&time_, sizeof time_), raw(&steps_, sizeof steps_), raw(&dissipated_, sizeof dissipated_),
            raw(&wall_work_, sizeof wall_work_);
        const std::size_t builds = neighbors_.builds();
        raw(&builds, sizeof builds);
        std::vector<ListedPair> listed(pairs_.size());  // the checkpoint's record: pair and its history
        for (std::size_t k = 0; k < pairs_.size(); ++k) listed[k] = {pairs_[k].i, pairs_[k].j, states_[k]};
        vec(neighbors_.built_at()), vec(listed);
        for (const auto& w : wall_state_) vec(w);
        if (!out) throw std::runtime_error("cannot write checkpoint");
    }

    void load(std::istream& in) {
        auto raw = [&](void* data, std::size_t bytes) {
            in.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes));
            if (!in) throw std::runtime_error("checkpoint truncated or unreadable");
        };
        auto vec = [&](auto& v) {
            std::uint64_t n = 0;
            raw(&n, sizeof n);
            if (n > (1ULL << 34)) throw std::runtime_error("checkpoint corrupt (array of " + std::to_string(n) + ")");
            v.resize(n);
            raw(v.data(), n * sizeof(v[0]));
        };
        char magic[sizeof checkpoint_magic];
        raw(magic, sizeof magic);
        if (std::memcmp(magic, checkpoint_magic, sizeof magic) != 0)
            throw std::runtime_error(std::string("not a demscale checkpoint of this version (") + checkpoint_magic +
                                     "; one from an older demscale cannot be resumed: start the run again)");
        std::uint8_t ledger = 0;
        raw(&ledger, sizeof ledger);
        if (ledger != Ledger)
            throw std::runtime_error(std::string("checkpoint written with the energy ledger ") + (ledger ? "on" : "off") +
                                     ": resume it with the ledger " + (ledger ? "on" : "off") + " too");
        vec(p_.position), vec(p_.velocity), vec(p_.angular_velocity), vec(p_.force), vec(p_.torque);
        vec(p_.radius), vec(p_.mass), vec(p_.inertia), vec(p_.species), vec(p_.fixed);
        raw(&time_, sizeof time_), raw(&steps_, sizeof steps_), raw(&dissipated_, sizeof dissipated_),
            raw(&wall_work_, sizeof wall_work_);
        std::size_t builds = 0;
        raw(&builds, sizeof builds);
        std::vector<Vec3> built_at;
        std::vector<ListedPair> records;
        vec(built_at), vec(records);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> listed;
        pairs_.clear(), states_.clear();
        for (const auto& q : records) listed.emplace_back(q.i, q.j), pairs_.push_back({q.i, q.j}), states_.push_back(q.state);
        engaged_.assign(pairs_.size(), 1);  // not recorded: the first step evaluates every pair
        neighbors_.restore(std::move(built_at), std::move(listed), builds);
        for (auto& w : wall_state_) vec(w);
        for (auto& w : wall_engaged_) w.assign(p_.size(), 1);
        index_particles();
        index_incidence();
    }

    // Momenta about the origin: Σ m v and Σ (x × m v + I ω).
    Vec3 linear_momentum() const {
        Vec3 m = Vec3::Zero();
        for (std::size_t i = 0; i < p_.size(); ++i) m += p_.mass[i] * p_.velocity[i];
        return m;
    }
    Vec3 angular_momentum() const {
        Vec3 l = Vec3::Zero();
        for (std::size_t i = 0; i < p_.size(); ++i)
            l += p_.position[i].cross(p_.mass[i] * p_.velocity[i]) + p_.inertia[i] * p_.angular_velocity[i];
        return l;
    }

private:
    static constexpr char checkpoint_magic[16] = "demscale-ckpt-5";
    // Below this many items a loop runs serially: thread start-up would cost more than the work.
    static constexpr long parallel_threshold = 512;
    // States are written as bytes: plain fixed-size data only.
    static_assert(std::is_standard_layout_v<LawState>);

    struct PairShape {  // what a pair's radii and masses give
        double r_eff, sqrt_r_eff, m_eff;  // R* (m), √R* (m^½), m* (kg)
    };
    struct PairIndex {
        std::uint32_t i, j;  // i < j
    };
    struct ListedPair {  // a checkpoint's record of one listed pair
        std::uint32_t i, j;
        LawState state;
    };
    struct PairResult {  // what one pair contributes this step
        Vec3 force_i = Vec3::Zero(), torque_i = Vec3::Zero(), torque_j = Vec3::Zero();
    };
    struct alignas(64) ThreadLedger {  // one thread's share of this step's ledger (own cache line)
        Dissipation lost;
        double wall_power = 0;  // W, Σ force on a particle · velocity of the wall touching it
    };

    // What the particles' radii and masses give, once (the same bits as computing it where used):
    // ½dt/m and ½dt/I for half_kick, s/kg and s/(kg m²), and each particle's shape against a wall.
    void index_particles() {
        kick_.resize(p_.size()), wall_shapes_.resize(p_.size());
        for (std::size_t i = 0; i < p_.size(); ++i)
            kick_[i] = {0.5 * dt_ / p_.mass[i], 0.5 * dt_ / p_.inertia[i]}, wall_shapes_[i] = pair_shape(i, a_wall);
    }

    void half_kick() {
        for (std::size_t i = 0; i < p_.size(); ++i) {
            if (p_.fixed[i]) continue;
            p_.velocity[i] += kick_[i].translation * p_.force[i];
            p_.angular_velocity[i] += kick_[i].rotation * p_.torque[i];
        }
    }

    // New pair list: the pairs within the skin of touching (only those can touch before the next
    // rebuild), with the history of those already listed, plus every pair a liquid bridge still
    // holds, however far it has stretched. The list need not reach the rupture gap: a bridge forms
    // only at contact, and this keeps it until it ruptures. Both lists are sorted by (i, j), so
    // one merge pass does it, and the acting pairs keep their order (the same bits as a list that
    // reaches the rupture gap).
    void rebuild() {
        std::vector<PairIndex> old;
        std::vector<LawState> old_states;
        std::vector<std::uint8_t> old_engaged;
        old.swap(pairs_), old_states.swap(states_), old_engaged.swap(engaged_);
        neighbors_.build(p_);
        const auto& near = neighbors_.pairs();
        pairs_.reserve(near.size()), states_.reserve(near.size()), engaged_.reserve(near.size());
        auto add = [&](PairIndex q, const LawState& state, std::uint8_t engaged) {
            pairs_.push_back(q), states_.push_back(state), engaged_.push_back(engaged);
        };
        auto keep_bridged = [&](std::size_t k) {
            if (law_.acts_across_gap(old_states[k])) add(old[k], old_states[k], 1);
        };
        std::size_t k = 0;
        for (const auto& [i, j] : near) {
            for (; k < old.size() && std::make_pair(old[k].i, old[k].j) < std::make_pair(i, j); ++k) keep_bridged(k);
            if (k < old.size() && old[k].i == i && old[k].j == j) add(old[k], old_states[k], old_engaged[k]), ++k;
            else add({i, j}, LawState{}, 0);
        }
        for (; k < old.size(); ++k) keep_bridged(k);
        index_incidence();
    }

    // For each particle, the pairs it belongs to in ascending pair order (CSR), with its side:
    // entry = 2·pair + (0 if it is i, 1 if it is j); and each pair's shape.
    void index_incidence() {
        incidence_start_.assign(p_.size() + 1, 0);
        for (const auto& q : pairs_) ++incidence_start_[q.i + 1], ++incidence_start_[q.j + 1];
        for (std::size_t k = 0; k < p_.size(); ++k) incidence_start_[k + 1] += incidence_start_[k];
        incidence_.resize(2 * pairs_.size());
        std::vector<std::uint32_t> fill(incidence_start_.begin(), incidence_start_.end() - 1);
        for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
            incidence_[fill[pairs_[k].i]++] = 2 * k;
            incidence_[fill[pairs_[k].j]++] = 2 * k + 1;
        }
        results_.assign(pairs_.size(), PairResult{});
        shapes_.resize(pairs_.size());
        for (std::size_t k = 0; k < pairs_.size(); ++k) shapes_[k] = pair_shape(pairs_[k].i, pairs_[k].j);
    }

    // R*, √R* and m* of particle i with j, or with a wall (j = a_wall: i's own radius and mass). m*
    // is the mobile one's mass alone when the other is fixed (like a wall).
    PairShape pair_shape(std::size_t i, std::size_t j) const {
        const double ri = p_.radius[i], mi = p_.mass[i];
        if (j == a_wall) return {ri, std::sqrt(ri), mi};
        const double rj = p_.radius[j], mj = p_.mass[j], r_eff = ri * rj / (ri + rj);
        return {r_eff, std::sqrt(r_eff), p_.fixed[i] ? mj : p_.fixed[j] ? mi : mi * mj / (mi + mj)};
    }

    static constexpr std::size_t a_wall = static_cast<std::size_t>(-1);

    // 1/(I + m R²) of particle k, the inverse of its inertia about a contact point; 0 if fixed.
    double rolling_compliance(std::size_t k) const {
        return p_.fixed[k] ? 0.0 : 1.0 / (p_.inertia[k] + p_.mass[k] * p_.radius[k] * p_.radius[k]);
    }

    // Contact of particle i with partner j (or a_wall) moving with velocity vj and spin wj, radius rj
    // (0 for a wall), at separation d = x_i − x_j, dist = |d| (the caller's range check already
    // needed it), with the pair's shape (shapes_ or wall_shapes_).
    DEMSCALE_HOT ContactPair pair_geometry(std::size_t i, const Vec3& d, double dist, const Vec3& vj, const Vec3& wj, double rj,
                                           const PairShape& shape, std::size_t j) const {
        const bool wall = j == a_wall;
        ContactPair c;
        const double ri = p_.radius[i];
        c.overlap = ri + rj - dist;
        c.normal = d / dist;
        c.r_eff = shape.r_eff;
        c.sqrt_r_eff = shape.sqrt_r_eff;
        c.contact_radius = c.overlap > 0 ? std::sqrt(c.r_eff * c.overlap) : 0.0;
        c.m_eff = shape.m_eff;
        c.dt = dt_;
        c.wall = wall;
        if (c.overlap <= 0 && !law_.needs_gap_velocity()) {  // apart: only cohesion acts, on the gap alone
            c.v_rel = c.v_tangential = c.w_rel = Vec3::Zero();
            return c;
        }
        // Contact point at the middle of the overlap (of the gap, for a viscous bridge); lever arms
        // from each centre.
        const double li = ri - 0.5 * c.overlap, lj = rj - 0.5 * c.overlap;
        c.v_rel = p_.velocity[i] + p_.angular_velocity[i].cross(-li * c.normal) - (vj + wj.cross(lj * c.normal));
        c.v_normal = c.v_rel.dot(c.normal);
        c.v_tangential = c.v_rel - c.v_normal * c.normal;
        c.w_rel = p_.angular_velocity[i] - wj;
        if (law_.rolling_damping() > 0) c.rolling_compliance = rolling_compliance(i) + (wall ? 0.0 : rolling_compliance(j));
        return c;
    }

    // What a listed pair contributes: nothing (beyond the law's reach, or apart with no bridge
    // holding it), a central force only (a bridge across a gap), or a contact's force and torques.
    enum class Acts { nothing, central, contact };

    // What listed pair (i, j) of that shape, with history s, contributes now, into out (left zero
    // where it does not act; a central force leaves the torques zero). A pair that stops acting
    // has its springs released.
    template <class L>
    DEMSCALE_HOT Acts pair_result(std::size_t i, std::size_t j, const PairShape& shape, LawState& s, double reach,
                                  L& lost, PairResult& out) const {
        const Vec3 d = p_.position[i] - p_.position[j];
        const double dist = d.norm(), gap = dist - p_.radius[i] - p_.radius[j];
        if (gap > reach || (gap > 0 && !law_.acts_across_gap(s))) {
            law_.release(s, lost);
            return Acts::nothing;
        }
        // A bridge across a gap pulls along the line of centres: no contact geometry needed. The
        // overlap and the force are computed as pair_geometry and force() compute them (same bits).
        // A viscous bridge also drags across the gap: the full geometry below.
        if (const double overlap = p_.radius[i] + p_.radius[j] - dist; gap > 0 && overlap <= 0 && !law_.needs_gap_velocity()) {
            out.force_i = (0.0 - law_.pull_apart(overlap, 0.0, dt_, false, s, lost)) * (d / dist);
            return Acts::central;
        }
        const ContactPair c =
            pair_geometry(i, d, dist, p_.velocity[j], p_.angular_velocity[j], p_.radius[j], shape, j);
        const ContactForce f = law_.force(c, s, lost);
        out.force_i = f.on_i;
        if (c.overlap <= 0 && !law_.needs_gap_velocity()) return Acts::central;  // gap rounded to 0: the same central pull
        const double li = p_.radius[i] - 0.5 * c.overlap, lj = p_.radius[j] - 0.5 * c.overlap;
        out.torque_i = (-li * c.normal).cross(f.tangential) + f.rolling_torque;
        out.torque_j = (lj * c.normal).cross(-f.tangential) - f.rolling_torque;
        return Acts::contact;
    }

    // pair_result for listed pair k, where a pair without history (engaged_[k] = 0: its state is
    // zero) that is surely apart is passed over: it would do nothing and keep its zero state, so it
    // needs no square root and no access to its state. The margin on the squared distance (1e-12
    // relative) is far above rounding: the decision is pair_result's own.
    template <class L>
    DEMSCALE_HOT Acts listed_result(std::size_t k, double reach, L& lost, PairResult& out) {
        const std::size_t i = pairs_[k].i, j = pairs_[k].j;
        if (!engaged_[k]) {
            const double touch = p_.radius[i] + p_.radius[j];
            if ((p_.position[i] - p_.position[j]).squaredNorm() > touch * touch * (1 + 1e-12)) return Acts::nothing;
        }
        const Acts acts = pair_result(i, j, shapes_[k], states_[k], reach, lost, out);
        engaged_[k] = acts != Acts::nothing;  // released: zero again
        return acts;
    }

    void compute_forces() {
        const double reach = law_.range();
        const long n_pairs = static_cast<long>(pairs_.size()), n = static_cast<long>(p_.size());
        // The ledger is summed per thread and then in thread order: deterministic for a given thread
        // count, and no per-pair storage for it.
        if constexpr (Ledger) thread_ledger_.assign(static_cast<std::size_t>(omp_get_max_threads()), ThreadLedger{});
        for (std::size_t i = 0; i < p_.size(); ++i) p_.force[i] = p_.mass[i] * gravity_, p_.torque[i] = Vec3::Zero();
        if (n_pairs <= parallel_threshold || omp_get_max_threads() == 1) {
            // One thread: each pair that acts adds to its two particles at once. Every particle still
            // sums its pairs in ascending pair order, after gravity: the same bits as the gather
            // below (which also adds the zeros of pairs that do not act, and the zero torques of
            // central forces; sums that start at +0 or a non-zero value are unchanged by adding ±0).
            Lost lost;
            for (std::size_t k = 0; k < pairs_.size(); ++k) {
                PairResult r;
                const Acts acts = listed_result(k, reach, lost, r);
                if (acts == Acts::nothing) continue;
                const PairIndex q = pairs_[k];
                p_.force[q.i] += r.force_i, p_.force[q.j] -= r.force_i;
                if (acts == Acts::contact) p_.torque[q.i] += r.torque_i, p_.torque[q.j] += r.torque_j;
            }
            if constexpr (Ledger) thread_ledger_[0].lost += lost;
        } else {
            // Threads: pair results into a buffer, then each particle gathers its own (no races).
#pragma omp parallel
            {
                Lost lost;
#pragma omp for schedule(static)
                for (long k = 0; k < n_pairs; ++k) {
                    PairResult& r = results_[static_cast<std::size_t>(k)];
                    r = PairResult{};
                    listed_result(static_cast<std::size_t>(k), reach, lost, r);
                }
                if constexpr (Ledger) thread_ledger_[static_cast<std::size_t>(omp_get_thread_num())].lost += lost;
            }
#pragma omp parallel for schedule(static) if (n > parallel_threshold)
            for (long ii = 0; ii < n; ++ii) {
                const std::size_t i = static_cast<std::size_t>(ii);
                Vec3 f = p_.force[i], t = p_.torque[i];
                for (std::uint32_t e = incidence_start_[i]; e < incidence_start_[i + 1]; ++e) {
                    const PairResult& r = results_[incidence_[e] / 2];
                    if (incidence_[e] % 2 == 0) f += r.force_i, t += r.torque_i;
                    else f -= r.force_i, t += r.torque_j;
                }
                p_.force[i] = f;
                p_.torque[i] = t;
            }
        }
        std::string wall_error;
        wall_bounds_.clear();
        for (const Wall& wall : walls_) wall_bounds_.emplace_back(wall, time_);
#pragma omp parallel if (n * static_cast<long>(walls_.size()) > parallel_threshold)
        {
            Lost lost;
            double wall_power = 0;  // W, Σ force on a particle · velocity of the wall touching it
#pragma omp for schedule(static)
            for (long ii = 0; ii < n; ++ii) {
                const std::size_t i = static_cast<std::size_t>(ii);
                if (p_.fixed[i]) continue;  // a fixed grain may sit in a wall (a floor's half-buried grains)
                for (std::size_t w = 0; w < walls_.size(); ++w) {
                    std::uint8_t& engaged = wall_engaged_[w][i];
                    auto out_of_reach = [&] {  // its springs let go (a state without history has nothing to release)
                        if (engaged) law_.release(wall_state_[w][i], lost), engaged = 0;
                    };
                    if (wall_bounds_[w].surely_farther_than(p_.position[i], p_.radius[i] + reach)) {
                        out_of_reach();  // as the range check below would
                        continue;
                    }
                    const WallPoint wp = closest_wall_point(walls_[w], p_.position[i], time_);
                    if (wp.behind) {
#pragma omp critical
                        wall_error = "particle " + std::to_string(i) + " left the domain through wall " + std::to_string(w) +
                                     " at step " + std::to_string(steps_);
                        continue;
                    }
                    const Vec3 d = p_.position[i] - wp.point;
                    const double dist = d.norm();
                    if (dist - p_.radius[i] > reach) {
                        out_of_reach();
                        continue;
                    }
                    engaged = 1;
                    const ContactPair c = pair_geometry(i, d, dist, wp.velocity, Vec3::Zero(), 0.0, wall_shapes_[i], a_wall);
                    const ContactForce f = law_.force(c, wall_state_[w][i], lost);
                    p_.force[i] += f.on_i;
                    p_.torque[i] += (-(p_.radius[i] - 0.5 * c.overlap) * c.normal).cross(f.tangential) + f.rolling_torque;
                    if constexpr (Ledger) wall_power += f.on_i.dot(wp.velocity);
                }
            }
            if constexpr (Ledger) {
                auto& mine = thread_ledger_[static_cast<std::size_t>(omp_get_thread_num())];
                mine.lost += lost, mine.wall_power += wall_power;
            }
        }
        if (!wall_error.empty()) throw std::runtime_error(wall_error);
        if constexpr (Ledger) {
            for (const ThreadLedger& t : thread_ledger_) dissipated_ += t.lost, wall_work_ += t.wall_power * dt_;
        }
        for (std::size_t i = 0; i < p_.size(); ++i)
            if (!p_.force[i].allFinite() || !p_.torque[i].allFinite()) throw std::runtime_error(non_finite_report(i, "force on"));
        if (Ledger && !std::isfinite(dissipated_.total() + wall_work_))  // after the forces: they name the contact
            throw std::runtime_error("non-finite energy ledger at step " + std::to_string(steps_) + " (t = " +
                                     std::to_string(time_) + " s): a contact law booked a non-finite loss");
    }

    // Why particle i got a non-finite force, torque or position ("what": "force on", "position of"):
    // its own state, or the first contact (in pair order, then walls) whose contribution is not finite.
    std::string non_finite_report(std::size_t i, const std::string& what) const {
        std::string why = "non-finite " + what + " particle " + std::to_string(i) + " at step " + std::to_string(steps_) +
                          " (t = " + std::to_string(time_) + " s)";
        if (!p_.velocity[i].allFinite() || !p_.angular_velocity[i].allFinite()) return why + ": its velocity is not finite";
        if (!p_.position[i].allFinite()) return why + ": its position is not finite";
        for (std::uint32_t e = incidence_start_[i]; e < incidence_start_[i + 1]; ++e) {
            // Evaluated again on a copy of the contact's history (the step's own results are not kept).
            const PairIndex q = pairs_[incidence_[e] / 2];
            LawState copy = states_[incidence_[e] / 2];
            Lost none;  // booked into nothing kept
            PairResult r;
            pair_result(q.i, q.j, shapes_[incidence_[e] / 2], copy, law_.range(), none, r);
            if (r.force_i.allFinite() && r.torque_i.allFinite() && r.torque_j.allFinite()) continue;
            const std::size_t other = q.i == i ? q.j : q.i;
            const double gap = (p_.position[i] - p_.position[other]).norm() - p_.radius[i] - p_.radius[other];
            return why + ", from its contact with particle " + std::to_string(other) + " (gap " + std::to_string(gap) + " m)";
        }
        for (std::size_t w = 0; w < walls_.size(); ++w)
            if (const auto c = wall_contact(walls_[w], i))
                return why + ", from its contact with wall " + std::to_string(w) + " (overlap " + std::to_string(c->overlap) + " m)";
        return why;
    }

    // The contact geometry of particle i with a wall, if within the law's range of it.
    std::optional<ContactPair> wall_contact(const Wall& wall, std::size_t i) const {
        if (p_.fixed[i]) return std::nullopt;
        const WallPoint wp = closest_wall_point(wall, p_.position[i], time_);
        const Vec3 d = p_.position[i] - wp.point;
        const double dist = d.norm();
        if (wp.behind || dist - p_.radius[i] > law_.range()) return std::nullopt;
        return pair_geometry(i, d, dist, wp.velocity, Vec3::Zero(), 0.0, wall_shapes_[i], a_wall);
    }

    Particles p_;
    struct Kick {
        double translation, rotation;  // ½dt/m, ½dt/I
    };
    std::vector<Kick> kick_;
    Law law_;
    std::vector<Wall> walls_;
    std::vector<WallBound> wall_bounds_;  // this step's, one per wall
    Vec3 gravity_;
    double dt_;
    NeighborList neighbors_;
    // The listed pairs in (i, j) order, each with its contact history and whether that history may
    // be non-zero (0: surely zero). Apart, three arrays: the pair loop reads a pair's history only
    // when it may act.
    std::vector<PairIndex> pairs_;
    std::vector<LawState> states_;
    std::vector<std::uint8_t> engaged_;
    std::vector<PairShape> shapes_;       // per listed pair
    std::vector<PairShape> wall_shapes_;  // per particle, against any wall
    std::vector<PairResult> results_;
    std::vector<std::uint32_t> incidence_start_, incidence_;
    std::vector<ThreadLedger> thread_ledger_;
    std::vector<std::vector<LawState>> wall_state_;        // per wall, per particle
    std::vector<std::vector<std::uint8_t>> wall_engaged_;  // per wall, per particle: 0 when its state is surely zero
    Dissipation dissipated_;  // so far, J
    double wall_work_ = 0;    // J done by walls on particles so far
    double time_ = 0;
    std::size_t steps_ = 0;
};

}  // namespace demscale::dem
