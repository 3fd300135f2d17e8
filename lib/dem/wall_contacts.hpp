// The particle–wall contacts of the engine: per wall and particle the contact history and whether
// it may be non-zero, each particle's shape against a wall, the spheres near each wall (the only
// ones a step looks at), and the forces of a step, particle by particle (a particle's walls in wall
// order), with the walls' power for the ledger. SI units.
#pragma once

#include <algorithm>
#include <cstdint>
#include <omp.h>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/memory_use.hpp"
#include "dem/checkpoint.hpp"
#include "dem/contact_geometry.hpp"
#include "dem/cross.hpp"
#include "dem/energy_ledger.hpp"
#include "dem/neighbor_list.hpp"
#include "dem/particles.hpp"
#include "dem/walls.hpp"
#include "dem/work_split.hpp"

namespace demscale::dem {

template <class Law, bool Ledger>
class WallContacts {
public:
    using Lost = typename EnergyLedger<Ledger>::Lost;
    using LawState = typename Law::template StateFor<Lost>;

    WallContacts(std::size_t walls, std::size_t particles)
        : state_(walls, std::vector<LawState>(particles)), engaged_(walls, std::vector<std::uint8_t>(particles, 0)) {}

    // Each particle's shape against any wall, once its radius and mass are known.
    void index(const Particles& p) {
        shapes_.resize(p.size());
        for (std::size_t i = 0; i < p.size(); ++i) shapes_[i] = pair_shape(p, i, a_wall);
    }

    // After the engine reordered its spheres (sphere k is now the one that was at order[k]): each
    // contact's history follows its sphere. index() follows.
    void reorder(const std::vector<std::uint32_t>& order) {
        for (auto& states : state_) gather(states, order);
        for (auto& engaged : engaged_) gather(engaged, order);
        stale_ = true;  // the marks are by the old order (a build follows, which refreshes them too)
    }

    struct Escape {  // a particle found behind a wall: it left the domain through it
        std::size_t particle, wall;
    };

    // A step's wall forces come in runs of spheres, each run by one thread (the engine's step,
    // simulation.hpp). prepare() draws the runs and returns their number; add_run_forces adds run
    // `part`'s forces. The runs are one per thread the run was given (`given`), whatever number
    // of threads runs this step (the ledger's sums, per share, stay the same bits). `neighbors`:
    // the engine's list, whose build positions and skin bound how far a sphere has moved
    // (refresh_near). `sphere_runs`: the pair loop's runs of spheres (PairShares::spheres), which
    // the runs follow when there are `given` of them: a sphere's state then stays on one core,
    // and its thread may add its walls before the barrier that its pairs need (faces).
    int prepare(const Particles& p, const Law& law, const std::vector<Wall>& walls, double time, int given,
                const NeighborList& neighbors, const std::vector<std::size_t>& sphere_runs) {
        escape_.reset();
        refresh_near(p, walls, time, law.range(), neighbors);
        bounds_.clear();
        for (const Wall& wall : walls) bounds_.emplace_back(wall, time);
        // Without the ledger the threads take the marked spheres (near_list_) of their runs;
        // before the pairs are shared, runs of the marked spheres of about equal work, each wall
        // contact a sphere had last step weighing wall_acting_cost (the pour puts the floor's
        // spheres first: equal counts left one thread 2.8 times the other's work,
        // docs/performance.md). With the ledger, all the spheres: its sums are per share and must
        // not follow the engaged flags or the marks, which a checkpoint does not carry.
        listed_ = Ledger ? nullptr : near_list_.data();  // item k is sphere listed_[k]
        const std::size_t items = Ledger ? p.size() : near_list_.size();
        const int parts = static_cast<long>(items * walls.size()) > parallel_threshold ? given : 1;
        follows_runs_ = sphere_runs.size() == static_cast<std::size_t>(parts) + 1;
        if (follows_runs_) {
            split_.resize(sphere_runs.size());
            for (std::size_t t = 0; t < split_.size(); ++t) {
                const auto first_marked = std::lower_bound(near_list_.begin(), near_list_.end(), sphere_runs[t]);
                split_[t] = Ledger ? sphere_runs[t] : static_cast<std::size_t>(first_marked - near_list_.begin());
            }
        } else {
            split_by_work(split_, items, parts, Ledger ? 0 : wall_acting_cost, [&](std::size_t k) { return acting_walls(listed_[k]); });
        }
        return parts;
    }
    // Whether prepare()'s runs are the pair loop's runs of spheres.
    bool follows_sphere_runs() const { return follows_runs_; }

    // Which of a run's spheres add_run_forces takes: all, or those off / on the slabs' faces.
    enum class Take { all, off_faces, on_faces };

    // Adds the wall forces and torques of run `part`'s spheres (in `take`, where `faces` lists
    // the faces' spheres of the run, ascending), each sphere's walls in wall order; `lost` and
    // `wall_power` (W, Σ force on a sphere · velocity of the wall touching it) get the run's
    // losses. A sphere found behind a wall is kept for escape().
    void add_run_forces(int part, Particles& p, const Law& law, const std::vector<Wall>& walls, double time, double dt,
                        Lost& lost, double& wall_power, Take take = Take::all, std::span<const std::uint32_t> faces = {}) {
        const double reach = law.range();
        auto sphere_forces = [&](std::size_t i) {
            if (!near_any_[i] || p.fixed[i]) return;  // a fixed grain may sit in a wall (a floor's half-buried grains)
            for (std::size_t w = 0; w < walls.size(); ++w) {
                if (!near_[w][i]) continue;  // surely out of its reach and holding nothing (refresh_near)
                std::uint8_t& engaged = engaged_[w][i];
                auto out_of_reach = [&] {  // its springs let go (a state without history has nothing to release)
                    if (engaged) law.release(state_[w][i], lost), engaged = 0;
                };
                if (bounds_[w].surely_farther_than(p.position[i], p.radius[i] + reach)) {
                    out_of_reach();  // as the range check below would
                    continue;
                }
                const WallPoint wp = closest_wall_point(walls[w], p.position[i], time);
                if (wp.behind) {
#pragma omp critical
                    escape_ = Escape{i, w};
                    continue;
                }
                const Vec3 d = p.position[i] - wp.point;
                const double dist = d.norm();
                if (dist - p.radius[i] > reach) {
                    out_of_reach();
                    continue;
                }
                engaged = 1;
                const ContactPair c = contact_geometry(law, p, dt, i, d, dist, wp.velocity, Vec3::Zero(), 0.0, shapes_[i], a_wall);
                const ContactForce f = law.force(c, state_[w][i], lost);
                p.force[i] += f.on_i;
                p.torque[i] += cross(-(p.radius[i] - 0.5 * c.overlap) * c.normal, f.tangential) + f.rolling_torque;
                if constexpr (Ledger) wall_power += f.on_i.dot(wp.velocity);
            }
        };
        if (take == Take::on_faces) {
            for (const std::uint32_t i : faces) sphere_forces(i);
            return;
        }
        auto face = faces.begin();  // the next face at or after the sphere (both ascending)
        for (std::size_t k = split_[static_cast<std::size_t>(part)]; k < split_[static_cast<std::size_t>(part) + 1]; ++k) {
            const std::size_t i = listed_ ? listed_[k] : k;
            if (take == Take::off_faces) {
                while (face != faces.end() && *face < i) ++face;
                if (face != faces.end() && *face == i) continue;
            }
            sphere_forces(i);
        }
    }

    // The sphere and wall of an escape the last step found (the caller stops the run).
    const std::optional<Escape>& escape() const { return escape_; }

    // What particle i's walls cost a step, in listed pairs' tests (work_split.hpp), as of the
    // last step: its checks when it is marked near a wall, and its acting contacts.
    std::size_t work_of(std::size_t i) const {
        const bool near = !stale_ && i < near_any_.size() && near_any_[i];
        return (near ? wall_check_in_pair_tests : 0) + acting_cost * acting_walls(i);
    }

    // The contact geometry of particle i with a wall, if within the law's range of it.
    std::optional<ContactPair> contact(const Particles& p, const Law& law, const Wall& wall, double time, double dt,
                                       std::size_t i) const {
        if (p.fixed[i]) return std::nullopt;
        const WallPoint wp = closest_wall_point(wall, p.position[i], time);
        const Vec3 d = p.position[i] - wp.point;
        const double dist = d.norm();
        if (wp.behind || dist - p.radius[i] > law.range()) return std::nullopt;
        return contact_geometry(law, p, dt, i, d, dist, wp.velocity, Vec3::Zero(), 0.0, shapes_[i], a_wall);
    }

    // Adds what the wall contacts hold now to e, J (wall by wall, particle by particle).
    void add_stored_energy(StoredEnergy& e, const Particles& p, const Law& law, const std::vector<Wall>& walls, double time,
                           double dt) const {
        for (std::size_t w = 0; w < walls.size(); ++w)
            for (std::size_t i = 0; i < p.size(); ++i)
                if (const auto c = contact(p, law, walls[w], time, dt, i)) e += law.stored_energy(*c, state_[w][i]);
    }

    // Forgets wall `index` with its contact history; the energy its contacts held leaves with it,
    // booked as work the wall took away.
    void remove(std::size_t index, const Particles& p, const Law& law, const Wall& wall, double time, double dt,
                EnergyLedger<Ledger>& ledger) {
        if constexpr (Ledger)
            for (std::size_t i = 0; i < p.size(); ++i)
                if (const auto c = contact(p, law, wall, time, dt, i)) ledger.wall_took(law.stored_energy(*c, state_[index][i]).total());
        state_.erase(state_.begin() + static_cast<long>(index));
        engaged_.erase(engaged_.begin() + static_cast<long>(index));
        stale_ = true;
    }

    // The first wall (in wall order) particle i touches, described ("from its contact with wall 1
    // (overlap … m)").
    std::optional<std::string> contact_report(std::size_t i, const Particles& p, const Law& law, const std::vector<Wall>& walls,
                                              double time, double dt) const {
        for (std::size_t w = 0; w < walls.size(); ++w)
            if (const auto c = contact(p, law, walls[w], time, dt, i))
                return ", from its contact with wall " + std::to_string(w) + " (overlap " + std::to_string(c->overlap) + " m)";
        return std::nullopt;
    }

    // Checkpoint: the histories, wall by wall. The engaged flags are not recorded: after a restore
    // the first step evaluates every contact.
    void write(CheckpointWriter& w) const {
        for (const auto& states : state_) w.array(states);
    }
    void read(CheckpointReader& r, std::size_t particles) {
        for (auto& states : state_) r.array(states);
        for (auto& e : engaged_) e.assign(particles, 1);
        stale_ = true;
    }

    // What the wall contacts hold, by consumer (bytes).
    void add_memory(std::vector<MemoryItem>& out) const {
        out.push_back({"wall histories (per wall, per sphere)", capacity_bytes(state_) + capacity_bytes(engaged_)});
        out.push_back({"wall shapes and near lists", capacity_bytes(shapes_) + capacity_bytes(near_) + capacity_bytes(near_any_) +
                                                          capacity_bytes(near_list_) + capacity_bytes(split_)});
    }

private:
    // How many walls held particle i last step (contacts with history).
    std::size_t acting_walls(std::size_t i) const {
        std::size_t acting = 0;
        for (const auto& engaged : engaged_) acting += engaged[i];
        return acting;
    }

    // Marks the spheres each wall may touch before the next refresh: those not surely farther
    // than r + reach + 2 skin from it where the neighbour list was built, and those it held last
    // step. Until the list's next build a sphere moves at most one skin from there (the list's
    // rebuild rule, neighbor_list.hpp), and the marks are refreshed before a wall has moved half a
    // skin: every unmarked sphere stays over half a skin out of reach and holds nothing, so
    // skipping it changes no bit. Refreshed at each build of the list, when a wall moved half a
    // skin or changed, and after a restore.
    void refresh_near(const Particles& p, const std::vector<Wall>& walls, double time, double reach, const NeighborList& neighbors) {
        const double skin = neighbors.cutoff_gap();
        bool fresh = !stale_ && near_builds_ == neighbors.builds() && near_walls_.size() == walls.size() && near_any_.size() == p.size();
        for (std::size_t w = 0; fresh && w < walls.size(); ++w) {
            const std::optional<double> shift = wall_shift(near_walls_[w], near_time_, walls[w], time);
            fresh = shift && *shift < 0.5 * skin;
        }
        if (fresh) return;
        const std::vector<Vec3>& from = neighbors.built_at();
        if (from.size() != p.size()) throw std::logic_error("wall contacts: the neighbour list is not built for these spheres");
        near_any_.assign(p.size(), 0);
        near_list_.clear();
        near_.resize(walls.size());
        std::vector<WallBound> bounds;
        for (std::size_t w = 0; w < walls.size(); ++w) bounds.emplace_back(walls[w], time), near_[w].resize(p.size());
        const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) if (n * static_cast<long>(walls.size()) > parallel_threshold)
        for (long k = 0; k < n; ++k) {
            const auto i = static_cast<std::size_t>(k);
            for (std::size_t w = 0; w < walls.size(); ++w) {
                near_[w][i] = engaged_[w][i] || !bounds[w].surely_farther_than(from[i], p.radius[i] + reach + 2 * skin);
                near_any_[i] |= near_[w][i];
            }
        }
        for (std::uint32_t i = 0; i < p.size(); ++i)
            if (near_any_[i]) near_list_.push_back(i);
        near_walls_ = walls, near_time_ = time, near_builds_ = neighbors.builds(), stale_ = false;
    }

    std::vector<std::vector<LawState>> state_;        // per wall, per particle
    std::vector<std::vector<std::uint8_t>> engaged_;  // per wall, per particle: 0 when its state is surely zero
    std::vector<PairShape> shapes_;                   // per particle, against any wall
    std::vector<WallBound> bounds_;                   // this step's, one per wall
    std::vector<std::size_t> split_;                  // each run's items this step (prepare)
    const std::uint32_t* listed_ = nullptr;           // item k is sphere listed_[k] (null: sphere k)
    bool follows_runs_ = false;                       // the runs are the pair loop's (prepare)
    std::optional<Escape> escape_;                    // found this step (add_run_forces)
    std::vector<std::vector<std::uint8_t>> near_;     // per wall, per particle: 1 when it may touch (refresh_near)
    std::vector<std::uint8_t> near_any_;              // per particle: 1 when it may touch some wall
    std::vector<std::uint32_t> near_list_;            // those particles, ascending
    std::vector<Wall> near_walls_;                    // the walls as they were at the last refresh,
    double near_time_ = 0;                            // at that time, s,
    std::size_t near_builds_ = 0;                     // after that many builds of the neighbour list
    bool stale_ = true;                               // walls or state changed: refresh at the next step
};

}  // namespace demscale::dem
