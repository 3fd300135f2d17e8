// The DEM engine for one contact law: particles, walls, gravity, velocity-Verlet integration
// (translation and rotation), the rebuild trigger of the Verlet neighbour list, and the checks
// that stop a run at the first non-finite number. The parts own their state: PairContacts (pairs,
// their history, the threaded gather), WallContacts, EnergyLedger, SphereOrder (the spheres' order
// against the input's), ThreadGovernor (the threads of a step); contact geometry is free
// functions (contact_geometry.hpp); checkpoints use one format (checkpoint.hpp). A step runs two
// parallel regions: the half kick with the drift, and the forces with the closing half kick
// (compute_forces). Trajectories are bit-identical for any thread count (the energy ledger's sums,
// per share of the work, for any thread count that runs the steps of a run given the same
// threads). A large scene's spheres are reordered cell by cell now and then (sphere_order.hpp):
// particles() is then in that order, input_index() names each sphere's place in the input, and
// in_input_order() gives the state as it was ordered. Momenta: particles.hpp. SI units.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <istream>
#include <omp.h>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/memory_use.hpp"
#include "core/input_error.hpp"
#include "dem/checkpoint.hpp"
#include "dem/contact_law.hpp"
#include "dem/energy_ledger.hpp"
#include "dem/neighbor_list.hpp"
#include "dem/thread_governor.hpp"
#include "dem/pair_contacts.hpp"
#include "dem/spatial_order.hpp"
#include "dem/sphere_order.hpp"
#include "dem/wall_contacts.hpp"
#include "dem/walls.hpp"

namespace demscale::dem {

// Ledger: book every loss and the walls' work (energy() then balances), or not (about 10 % faster;
// energy() then reports kinetic, gravitational and stored energy only).
template <class Law, bool Ledger = true>
class Simulation {
public:
    Simulation(Particles particles, Law law, std::vector<Wall> walls, Vec3 gravity, double dt, double skin,
               SpatialSort sort = {})
        : p_(std::move(particles)), law_(std::move(law)), walls_(std::move(walls)), gravity_(gravity), dt_(dt),
          neighbors_(skin), wall_contacts_(walls_.size(), p_.size()), order_(p_.size(), sort) {
        require_positive(dt, "dt");
        require_positive(skin, "skin");
        index_particles();
        rebuild();
        compute_forces();
    }

    // One velocity-Verlet step: half kick, drift, forces, half kick. On the threads the governor
    // chose (thread_governor.hpp); the caller's thread count is restored after the step.
    void step() {
        const ThreadsForStep threads(governor_);
        // One pass: half kick and drift, with the two largest shifts since the list's build. NaN
        // or inf anywhere makes the sum of the positions non-finite (in any order): one check.
        const bool built = neighbors_.built_for(p_);
        const Drifted drifted = over_spheres([&](std::size_t begin, std::size_t end) {
            half_kick(begin, end);
            // Locals, not the returned struct: Eigen's stores may alias any double in memory, so
            // a sum kept there went through memory at every sphere (a chain of store and load).
            double sum = 0;
            NeighborList::Shifts shifts;
            Vec3* const x = p_.position.data();
            const Vec3* const v = p_.velocity.data();
            for (std::size_t i = begin; i < end; ++i) {
                x[i] += dt_ * v[i], sum += x[i].sum();
                if (built) shifts.keep(neighbors_.squared_shift(p_, i));
            }
            return Drifted{sum, shifts};
        });
        if (!std::isfinite(drifted.sum))
            for (std::size_t i = 0; i < p_.size(); ++i)
                if (!p_.position[i].allFinite()) throw std::runtime_error(non_finite_report(i, "position of"));
        if (order_.due(p_.size(), steps_) || !built || neighbors_.needs_rebuild(drifted.shifts)) rebuild();
        compute_forces(AfterForces::half_kick);
        time_ += dt_;
        ++steps_;
    }

    const ThreadGovernor& governor() const { return governor_; }
    // Stops the governor: each step then runs on the threads OpenMP is set to (tests that switch
    // the count by hand); the work stays cut into the shares of the threads the run was given.
    void stop_governing() { governor_ = ThreadGovernor(1); }

    // The spheres in the engine's order (input_index() maps it to the input's).
    const Particles& particles() const { return p_; }
    Particles& particles() { return p_; }  // to move particles or set velocities; masses stay as built
    // Where each sphere stood in the input: particles()[k] is the input's sphere input_index()[k].
    const std::vector<std::uint32_t>& input_index() const { return order_.input_index(); }
    // The state now, in the input's order (a copy).
    Particles in_input_order() const { return order_.in_input_order(p_); }
    std::size_t spatial_sorts() const { return order_.sorts(); }
    std::vector<Wall>& walls() { return walls_; }  // e.g. to schedule the cone's lift

    // Takes a wall out of the scene (the slump cone after its lift), with its contact history.
    // The energy its contacts held leaves with it (booked as work the wall took away).
    void remove_wall(std::size_t index) {
        wall_contacts_.remove(index, p_, law_, walls_[index], time_, dt_, ledger_);
        walls_.erase(walls_.begin() + static_cast<long>(index));
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
        e.dissipated = ledger_.dissipated();
        e.wall_work = ledger_.wall_work();
        for (std::size_t i = 0; i < p_.size(); ++i) {
            if (p_.fixed[i]) continue;  // no motion, constant height
            e.kinetic += 0.5 * p_.mass[i] * p_.velocity[i].squaredNorm() +
                         0.5 * p_.inertia[i] * p_.angular_velocity[i].squaredNorm();
            e.gravitational -= p_.mass[i] * gravity_.dot(p_.position[i]);
        }
        pair_contacts_.add_stored_energy(e.stored, p_, law_, dt_);
        wall_contacts_.add_stored_energy(e.stored, p_, law_, walls_, time_, dt_);
        return e;
    }

    // Checkpoint: everything the next step depends on (particles with their current forces, time,
    // energies, the neighbour list's reference positions and pairs with contact history, wall
    // contact history), so that a restart continues bit for bit. Walls and the law come from the scene.
    void save(std::ostream& out) const {
        CheckpointWriter w(out, checkpoint_tag);
        w.value(std::uint8_t{Ledger});  // the histories' layout depends on it
        w.array(p_.position), w.array(p_.velocity), w.array(p_.angular_velocity), w.array(p_.force), w.array(p_.torque);
        w.array(p_.radius), w.array(p_.mass), w.array(p_.inertia), w.array(p_.species), w.array(p_.fixed);
        w.value(time_), w.value(steps_), ledger_.write(w);
        order_.write(w);
        w.value(neighbors_.builds());
        w.array(neighbors_.built_at());
        pair_contacts_.write(w);
        wall_contacts_.write(w);
    }

    void load(std::istream& in) {
        CheckpointReader r(in, checkpoint_tag,
                           std::string("not a demscale checkpoint of this version (") + checkpoint_tag +
                               "; one from an older demscale cannot be resumed: start the run again)");
        std::uint8_t ledger = 0;
        r.value(ledger);
        if (ledger != Ledger)
            throw std::runtime_error(std::string("checkpoint written with the energy ledger ") + (ledger ? "on" : "off") +
                                     ": resume it with the ledger " + (ledger ? "on" : "off") + " too");
        r.array(p_.position), r.array(p_.velocity), r.array(p_.angular_velocity), r.array(p_.force), r.array(p_.torque);
        r.array(p_.radius), r.array(p_.mass), r.array(p_.inertia), r.array(p_.species), r.array(p_.fixed);
        r.value(time_), r.value(steps_), ledger_.read(r);
        order_.read(r);
        std::size_t builds = 0;
        r.value(builds);
        std::vector<Vec3> built_at;
        r.array(built_at);
        auto listed = pair_contacts_.read(r, p_);
        neighbors_.restore(std::move(built_at), std::move(listed), builds);
        wall_contacts_.read(r, p_.size());
        index_particles();
    }

    // The engine's memory by consumer (its containers' capacities), bytes: the benchmark's breakdown.
    std::vector<MemoryItem> memory() const {
        std::vector<MemoryItem> out = {
            {"spheres (position, velocity, spin, force, torque, radius, mass, ...)", p_.bytes() + capacity_bytes(kick_)},
            {"neighbour list", neighbors_.bytes()},
        };
        pair_contacts_.add_memory(out);
        wall_contacts_.add_memory(out);
        return out;
    }

private:
    static constexpr CheckpointTag checkpoint_tag = "demscale-ckpt-9";

    // Sets the governor's thread count for one step and restores the caller's after it (also when
    // the step throws), then reports the step's end to the governor.
    struct ThreadsForStep {
        ThreadGovernor& governor;
        int outer = omp_get_max_threads();
        explicit ThreadsForStep(ThreadGovernor& g) : governor(g) {
            if (governor.active()) omp_set_num_threads(governor.threads());
        }
        ~ThreadsForStep() {
            if (!governor.active()) return;
            omp_set_num_threads(outer);
            governor.stepped(std::chrono::steady_clock::now());
        }
        ThreadsForStep(const ThreadsForStep&) = delete;
        ThreadsForStep& operator=(const ThreadsForStep&) = delete;
    };

    // What the particles' radii and masses give, once (the same bits as computing it where used):
    // ½dt/m and ½dt/I for half_kick, s/kg and s/(kg m²), and each particle's shape against a wall.
    void index_particles() {
        kick_.resize(p_.size());
        for (std::size_t i = 0; i < p_.size(); ++i) kick_[i] = {0.5 * dt_ / p_.mass[i], 0.5 * dt_ / p_.inertia[i]};
        wall_contacts_.index(p_);
    }

    // The half kick of spheres [begin, end).
    void half_kick(std::size_t begin, std::size_t end) {
        // Local pointers: Eigen's stores may alias any memory, the members would be read again
        // after each one.
        Vec3* const v = p_.velocity.data();
        Vec3* const w = p_.angular_velocity.data();
        const Vec3* const f = p_.force.data();
        const Vec3* const t = p_.torque.data();
        const Kick* const kick = kick_.data();
        const auto* const fixed = p_.fixed.data();
        for (std::size_t i = begin; i < end; ++i) {
            if (fixed[i]) continue;
            v[i] += kick[i].translation * f[i];
            w[i] += kick[i].rotation * t[i];
        }
    }

    // Spheres [begin, end) get their weight as force and no torque, the start of the step's sums.
    void set_gravity(std::size_t begin, std::size_t end) {
        Vec3* const f = p_.force.data();  // local pointers: see half_kick
        Vec3* const t = p_.torque.data();
        const double* const m = p_.mass.data();
        const Vec3 g = gravity_;
        for (std::size_t i = begin; i < end; ++i) f[i] = m[i] * g, t[i] = Vec3::Zero();
    }

    // Σ of the forces and torques of spheres [begin, end): non-finite when any of them is.
    double checked_sum(std::size_t begin, std::size_t end) const {
        const Vec3* const f = p_.force.data();
        const Vec3* const t = p_.torque.data();
        double sum = 0;
        for (std::size_t i = begin; i < end; ++i) sum += f[i].sum() + t[i].sum();
        return sum;
    }

    struct Drifted {  // what the drift of some spheres found
        double sum = 0;  // of their positions, m
        NeighborList::Shifts shifts;
        Drifted& operator+=(const Drifted& other) { return sum += other.sum, shifts += other.shifts, *this; }
    };

    // The runs of spheres the passes over them take, one per thread, [runs[t], runs[t + 1]): each
    // thread takes the spheres of its share of the pairs (PairContacts::sphere_shares): a
    // sphere's state is then written and read by one core through the step (pair forces, walls,
    // kicks, drift), and, the spheres sorted across the slabs, no cache line of it crosses between
    // the cores but at a slab's face. Runs of equal counts before the first shares are drawn or
    // when the pairs are too few to share.
    const std::vector<std::size_t>& sphere_runs() {
        const std::size_t n = p_.size();
        const std::vector<std::size_t>& shared = pair_contacts_.sphere_shares();
        if (shared.size() > 2 && shared.back() == n) return shared;
        const auto parts = static_cast<std::size_t>(static_cast<long>(n) > parallel_threshold ? given_threads_ : 1);
        equal_runs_.resize(parts + 1);
        for (std::size_t t = 0; t <= parts; ++t) equal_runs_[t] = n * t / parts;
        return equal_runs_;
    }

    // Runs pass(begin, end) over the sphere runs on the threads of the step; returns what the
    // runs return, added in run order.
    template <class Pass, class Result = std::invoke_result_t<Pass, std::size_t, std::size_t>>
    Result over_spheres(Pass pass) {
        const std::vector<std::size_t>& runs = sphere_runs();
        const int parts = static_cast<int>(runs.size()) - 1;
        if (parts == 1) return pass(runs[0], runs[1]);
        std::vector<Result> out(static_cast<std::size_t>(parts));
#pragma omp parallel for schedule(static, 1) num_threads(std::min(parts, omp_get_max_threads()))
        for (int part = 0; part < parts; ++part) {
            const auto t = static_cast<std::size_t>(part);
            out[t] = pass(runs[t], runs[t + 1]);
        }
        for (int part = 1; part < parts; ++part) out[0] += out[static_cast<std::size_t>(part)];
        return out[0];
    }

    void rebuild() {
        if (order_.due(p_.size(), steps_)) reorder_spatially();
        neighbors_.build(p_, &order_.input_index());  // pairs oriented by input order: a reorder flips none
        pair_contacts_.merge(neighbors_.pairs(), p_, law_);
    }

    // The spheres cell by cell through cells of the largest diameter (about the neighbour grid's,
    // without the skin, which must not change the order), each with its state, wall contacts and
    // pairs (renumbered; the next merge indexes them).
    void reorder_spatially() {
        const double r_max = *std::max_element(p_.radius.begin(), p_.radius.end());
        const int axis = longest_side(p_);  // the slabs' axis (over_spheres)
        const std::vector<std::uint32_t> order = spatial_order(p_, 2 * r_max, axis);
        pair_contacts_.cut_slabs_along(axis);
        const std::vector<std::uint32_t> new_index = order_.take(order, steps_);
        p_.reorder(order);
        wall_contacts_.reorder(order);
        index_particles();
        pair_contacts_.renumber(new_index);
    }

    enum class AfterForces { nothing, half_kick };  // what compute_forces does after the forces

    // The step's forces in one parallel region: each thread sets gravity on its run of spheres,
    // runs its share of the pairs and the walls of its spheres off the slabs' faces, times that
    // (the next draw of the slabs follows the times, slab_costs.hpp), and after one barrier
    // gathers its face spheres' pairs and adds their walls: every sphere gets gravity, its pairs
    // in pair order, then its walls in wall order, on any number of threads. A single barrier
    // lets a thread's pairs and walls together balance the other's (pairs and walls apart left
    // each phase waiting on its own, docs/performance.md). When the walls' runs are not the
    // pairs' (too few pairs or walls to share), all the walls follow the gathers. Then each
    // thread sums its spheres' forces and torques (NaN or inf anywhere makes a sum non-finite)
    // and, with `then` half_kick, once every sum is finite and no sphere escaped (a second
    // barrier), gives its spheres the step's last half kick; otherwise the step stops here,
    // naming the cause.
    void compute_forces(AfterForces then = AfterForces::nothing) {
        ledger_.begin_step(given_threads_);
        const int pair_parts = pair_contacts_.share(p_, given_threads_, [&](std::size_t i) { return wall_contacts_.work_of(i); });
        const std::vector<std::size_t>& pair_runs = pair_contacts_.sphere_shares();
        const int wall_parts = wall_contacts_.prepare(p_, law_, walls_, time_, given_threads_, neighbors_, pair_runs);
        const bool with_pairs = wall_contacts_.follows_sphere_runs();  // a run's walls by its pairs' thread
        const std::vector<std::size_t>& runs = sphere_runs();          // the checks' and the kick's
        const int run_parts = static_cast<int>(runs.size()) - 1;
        const int parts = std::max({pair_parts, wall_parts, run_parts});
        part_sums_.assign(static_cast<std::size_t>(parts), {});
        using Take = typename WallContacts<Law, Ledger>::Take;
#pragma omp parallel num_threads(std::min(parts, omp_get_max_threads()))
        {
            const int thread = omp_get_thread_num(), threads = omp_get_num_threads();
            auto mine = [&](int part) -> PartSums& { return part_sums_[static_cast<std::size_t>(part)]; };
            for (int part = thread; part < pair_parts; part += threads) {
                const auto start = std::chrono::steady_clock::now();
                set_gravity(pair_runs[static_cast<std::size_t>(part)], pair_runs[static_cast<std::size_t>(part) + 1]);
                pair_contacts_.add_share_forces(part, p_, law_, dt_, mine(part).pairs);
                if (with_pairs)
                    wall_contacts_.add_run_forces(part, p_, law_, walls_, time_, dt_, mine(part).walls, mine(part).wall_power,
                                                  Take::off_faces, pair_contacts_.faces_of(part));
                pair_contacts_.took(part, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
#pragma omp barrier
            for (int part = thread; part < pair_parts; part += threads) {
                pair_contacts_.gather_faces(part, p_);
                if (with_pairs)
                    wall_contacts_.add_run_forces(part, p_, law_, walls_, time_, dt_, mine(part).walls, mine(part).wall_power,
                                                  Take::on_faces, pair_contacts_.faces_of(part));
            }
            if (!with_pairs) {  // the walls' runs cross the pairs' faces: after the gathers
#pragma omp barrier
                for (int part = thread; part < wall_parts; part += threads)
                    wall_contacts_.add_run_forces(part, p_, law_, walls_, time_, dt_, mine(part).walls, mine(part).wall_power);
#pragma omp barrier
            }
            for (int part = thread; part < run_parts; part += threads) {
                mine(part).checked = checked_sum(runs[static_cast<std::size_t>(part)], runs[static_cast<std::size_t>(part) + 1]);
            }
            if (then == AfterForces::half_kick) {
#pragma omp barrier
                if (forces_sound(run_parts))
                    for (int part = thread; part < run_parts; part += threads)
                        half_kick(runs[static_cast<std::size_t>(part)], runs[static_cast<std::size_t>(part) + 1]);
            }
        }
        for (int part = 0; part < parts; ++part) {  // each share's pairs, then its walls, as the sums always were
            const PartSums& t = part_sums_[static_cast<std::size_t>(part)];
            ledger_.add(part, t.pairs), ledger_.add(part, t.walls, t.wall_power);
        }
        if (const auto& escape = wall_contacts_.escape())
            throw std::runtime_error("particle " + std::to_string(order_.input_index()[escape->particle]) + " left the domain through wall " +
                                     std::to_string(escape->wall) + " at step " + std::to_string(steps_));
        ledger_.end_step(dt_);
        if (!forces_sound(run_parts))  // find it (a sum of huge finite values may overflow: then none is found)
            for (std::size_t i = 0; i < p_.size(); ++i)
                if (!p_.force[i].allFinite() || !p_.torque[i].allFinite()) throw std::runtime_error(non_finite_report(i, "force on"));
        ledger_.check_finite(steps_, time_);
    }

    // Whether no sphere escaped and every run's sum of forces and torques is finite.
    bool forces_sound(int run_parts) const {
        if (wall_contacts_.escape()) return false;
        for (int part = 0; part < run_parts; ++part)
            if (!std::isfinite(part_sums_[static_cast<std::size_t>(part)].checked)) return false;
        return true;
    }

    // Why particle i got a non-finite force, torque or position ("what": "force on", "position of"):
    // its own state, or the first contact (in pair order, then walls) whose contribution is not finite.
    std::string non_finite_report(std::size_t i, const std::string& what) const {
        const std::string why = "non-finite " + what + " particle " + std::to_string(order_.input_index()[i]) + " at step " + std::to_string(steps_) +
                                " (t = " + std::to_string(time_) + " s)";
        if (!p_.velocity[i].allFinite() || !p_.angular_velocity[i].allFinite()) return why + ": its velocity is not finite";
        if (!p_.position[i].allFinite()) return why + ": its position is not finite";
        if (const auto pair = pair_contacts_.non_finite_contact(i, p_, law_, dt_, order_.input_index())) return why + *pair;
        if (const auto wall = wall_contacts_.contact_report(i, p_, law_, walls_, time_, dt_)) return why + *wall;
        return why;
    }

    Particles p_;
    struct Kick {
        double translation, rotation;  // ½dt/m, ½dt/I
    };
    std::vector<Kick> kick_;
    Law law_;
    std::vector<Wall> walls_;
    Vec3 gravity_;
    double dt_;
    NeighborList neighbors_;
    PairContacts<Law, Ledger> pair_contacts_;
    WallContacts<Law, Ledger> wall_contacts_;
    EnergyLedger<Ledger> ledger_;
    using Lost = typename EnergyLedger<Ledger>::Lost;
    struct alignas(64) PartSums {  // one share's sums in a step (own cache line: threads write them)
        Lost pairs, walls;
        double wall_power = 0;  // W
        double checked = 0;     // Σ of the run's forces and torques (compute_forces' check)
    };
    std::vector<PartSums> part_sums_;
    std::vector<std::size_t> equal_runs_;  // sphere_runs() before the pairs are shared
    double time_ = 0;
    std::size_t steps_ = 0;
    SphereOrder order_;  // the spheres' order against the input's, and when to reorder them
    // The threads the run was given (OpenMP's count at construction): the contact loops cut their
    // work into this many shares whatever number of threads the governor runs a step on, so the
    // ledger's sums, per share, are the same bits on one thread or all of them.
    int given_threads_ = omp_get_max_threads();
    ThreadGovernor governor_{given_threads_};
};

}  // namespace demscale::dem
