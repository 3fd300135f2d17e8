// The DEM engine for one contact law: particles, walls, gravity, velocity-Verlet integration
// (translation and rotation), the rebuild trigger of the Verlet neighbour list, and the checks
// that stop a run at the first non-finite number. The parts own their state: PairContacts (pairs,
// their history, the threaded gather), WallContacts, EnergyLedger; contact geometry is free
// functions (contact_geometry.hpp); checkpoints use one format (checkpoint.hpp). Trajectories are
// bit-identical for any thread count (the energy ledger's sums, per share of the work, for any
// thread count that runs the steps of a run given the same threads). A large scene's spheres are
// reordered cell by cell now and then (spatial_order.hpp): particles() is then in that order,
// input_index() names each sphere's place in the input, and in_input_order() gives the state as
// it was ordered. SI units.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <istream>
#include <numeric>
#include <omp.h>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "dem/checkpoint.hpp"
#include "dem/contact_law.hpp"
#include "dem/energy_ledger.hpp"
#include "dem/neighbor_list.hpp"
#include "dem/thread_governor.hpp"
#include "dem/pair_contacts.hpp"
#include "dem/spatial_order.hpp"
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
          neighbors_(skin), wall_contacts_(walls_.size(), p_.size()), sort_(sort), input_index_(p_.size()) {
        require_positive(dt, "dt");
        require_positive(skin, "skin");
        std::iota(input_index_.begin(), input_index_.end(), 0u);
        index_particles();
        rebuild();
        compute_forces();
    }

    // One velocity-Verlet step: half kick, drift, forces, half kick. On the threads the governor
    // chose (thread_governor.hpp); the caller's thread count is restored after the step.
    void step() {
        const ThreadsForStep threads(governor_);
        half_kick();
        // NaN or inf anywhere makes the sum non-finite (in any order): one check per step.
        const double probe = over_spheres([&](std::size_t begin, std::size_t end) {
            double sum = 0;
            for (std::size_t i = begin; i < end; ++i) p_.position[i] += dt_ * p_.velocity[i], sum += p_.position[i].sum();
            return sum;
        });
        if (!std::isfinite(probe))
            for (std::size_t i = 0; i < p_.size(); ++i)
                if (!p_.position[i].allFinite()) throw std::runtime_error(non_finite_report(i, "position of"));
        if (sort_due() || neighbors_.needs_rebuild(p_)) rebuild();
        compute_forces();
        half_kick();
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
    const std::vector<std::uint32_t>& input_index() const { return input_index_; }
    // The state now, in the input's order (a copy).
    Particles in_input_order() const {
        std::vector<std::uint32_t> slot(p_.size());
        for (std::uint32_t k = 0; k < slot.size(); ++k) slot[input_index_[k]] = k;
        Particles copy = p_;
        copy.reorder(slot);
        return copy;
    }
    std::size_t spatial_sorts() const { return sorts_; }
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
        w.array(input_index_), w.value(sorts_), w.value(sorted_at_);
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
        r.array(input_index_), r.value(sorts_), r.value(sorted_at_);
        std::size_t builds = 0;
        r.value(builds);
        std::vector<Vec3> built_at;
        r.array(built_at);
        auto listed = pair_contacts_.read(r, p_);
        neighbors_.restore(std::move(built_at), std::move(listed), builds);
        wall_contacts_.read(r, p_.size());
        index_particles();
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

    void half_kick() {
        over_spheres([&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                if (p_.fixed[i]) continue;
                p_.velocity[i] += kick_[i].translation * p_.force[i];
                p_.angular_velocity[i] += kick_[i].rotation * p_.torque[i];
            }
            return 0.0;
        });
    }

    // Runs pass(begin, end) over runs of the spheres that together cover them all, on the threads
    // of the step, and returns the sum of what the runs return. Each thread takes the spheres of
    // its share of the pairs (PairContacts::sphere_shares): a sphere's state is then written and
    // read by one core through the step (pair forces, walls, kicks, drift), and, the spheres
    // sorted across the slabs, no cache line of it crosses between the cores but at a slab's face.
    // Runs of equal counts before the first shares are drawn or when the pairs are too few to share.
    template <class Pass>
    double over_spheres(Pass pass) {
        const std::size_t n = p_.size();
        const std::vector<std::size_t>& shared = pair_contacts_.sphere_shares();
        const bool by_pairs = shared.size() > 2 && shared.back() == n;
        const int parts = by_pairs ? static_cast<int>(shared.size()) - 1 : static_cast<long>(n) > parallel_threshold ? given_threads_ : 1;
        auto first = [&](int part) { return by_pairs ? shared[part] : n * static_cast<std::size_t>(part) / static_cast<std::size_t>(parts); };
        if (parts == 1) return pass(std::size_t{0}, n);
        double sum = 0;
#pragma omp parallel for schedule(static, 1) num_threads(std::min(parts, omp_get_max_threads())) reduction(+ : sum)
        for (int part = 0; part < parts; ++part) sum += pass(first(part), first(part + 1));
        return sum;
    }

    // A reorder is due at the first build and every sort_.every_steps steps after it, at those
    // steps exactly (a rebuild is forced then): the order, hence each sphere's pair order, is then
    // the same whatever the skin, which only decides when the list is rebuilt in between.
    bool sort_due() const {
        return p_.size() > 1 && p_.size() >= sort_.min_particles && (sorts_ == 0 || steps_ - sorted_at_ >= sort_.every_steps);
    }

    void rebuild() {
        if (sort_due()) reorder_spatially();
        neighbors_.build(p_, &input_index_);  // pairs oriented by input order: a reorder flips none
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
        ++sorts_, sorted_at_ = steps_;
        std::vector<std::uint32_t> new_index(order.size()), input(order.size());
        for (std::uint32_t k = 0; k < order.size(); ++k) new_index[order[k]] = k, input[k] = input_index_[order[k]];
        input_index_ = std::move(input);
        p_.reorder(order);
        wall_contacts_.reorder(order);
        index_particles();
        pair_contacts_.renumber(new_index);
    }

    void compute_forces() {
        ledger_.begin_step(given_threads_);
        // The threads' shares, pairs and walls weighed together (the spheres' runs, over_spheres).
        pair_contacts_.share(p_, given_threads_, [&](std::size_t i) { return wall_contacts_.work_of(i); });
        over_spheres([&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) p_.force[i] = p_.mass[i] * gravity_, p_.torque[i] = Vec3::Zero();
            return 0.0;
        });
        pair_contacts_.add_forces(p_, law_, dt_, ledger_, given_threads_);
        if (const auto escape =
                wall_contacts_.add_forces(p_, law_, walls_, time_, dt_, ledger_, given_threads_, neighbors_, pair_contacts_.sphere_shares()))
            throw std::runtime_error("particle " + std::to_string(input_index_[escape->particle]) + " left the domain through wall " +
                                     std::to_string(escape->wall) + " at step " + std::to_string(steps_));
        ledger_.end_step(dt_);
        // NaN or inf in any force or torque makes the sum non-finite (in any order).
        const double probe = over_spheres([&](std::size_t begin, std::size_t end) {
            double sum = 0;
            for (std::size_t i = begin; i < end; ++i) sum += p_.force[i].sum() + p_.torque[i].sum();
            return sum;
        });
        if (!std::isfinite(probe))  // find it (a sum of huge finite values may overflow: then none is found)
            for (std::size_t i = 0; i < p_.size(); ++i)
                if (!p_.force[i].allFinite() || !p_.torque[i].allFinite()) throw std::runtime_error(non_finite_report(i, "force on"));
        ledger_.check_finite(steps_, time_);
    }

    // Why particle i got a non-finite force, torque or position ("what": "force on", "position of"):
    // its own state, or the first contact (in pair order, then walls) whose contribution is not finite.
    std::string non_finite_report(std::size_t i, const std::string& what) const {
        const std::string why = "non-finite " + what + " particle " + std::to_string(input_index_[i]) + " at step " + std::to_string(steps_) +
                                " (t = " + std::to_string(time_) + " s)";
        if (!p_.velocity[i].allFinite() || !p_.angular_velocity[i].allFinite()) return why + ": its velocity is not finite";
        if (!p_.position[i].allFinite()) return why + ": its position is not finite";
        if (const auto pair = pair_contacts_.non_finite_contact(i, p_, law_, dt_, input_index_)) return why + *pair;
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
    double time_ = 0;
    std::size_t steps_ = 0;
    SpatialSort sort_;
    std::vector<std::uint32_t> input_index_;  // each sphere's place in the input
    std::size_t sorts_ = 0, sorted_at_ = 0;   // reorders so far; the step of the last
    // The threads the run was given (OpenMP's count at construction): the contact loops cut their
    // work into this many shares whatever number of threads the governor runs a step on, so the
    // ledger's sums, per share, are the same bits on one thread or all of them.
    int given_threads_ = omp_get_max_threads();
    ThreadGovernor governor_{given_threads_};
};

}  // namespace demscale::dem
