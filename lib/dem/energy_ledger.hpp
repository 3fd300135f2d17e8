// The engine's energy ledger: what the contact laws dissipate and what the walls' motion does to
// the particles, summed per share of the work in a step and then in share order (deterministic for
// a given count of shares, whichever threads run them; no per-pair storage). Off (Ledger = false),
// it books nothing and costs nothing. SI.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "dem/checkpoint.hpp"
#include "dem/energy.hpp"

namespace demscale::dem {

template <bool Ledger>
class EnergyLedger {
public:
    using Lost = std::conditional_t<Ledger, Dissipation, NoDissipation>;  // what the laws book into

    struct alignas(64) Share {  // one share's part of a step (own cache line: threads write them)
        Dissipation lost;
        double wall_power = 0;  // W, Σ force on a particle · velocity of the wall touching it
    };

    void begin_step(int shares) {
        if constexpr (Ledger) shares_.assign(static_cast<std::size_t>(shares), Share{});
    }
    // What share `share` booked in this step (Ledger only).
    void add(int share, const Lost& lost, double wall_power = 0) {
        if constexpr (Ledger) {
            auto& mine = shares_[static_cast<std::size_t>(share)];
            mine.lost += lost, mine.wall_power += wall_power;
        }
    }
    // The step's shares into the totals, in share order.
    void end_step(double dt) {
        if constexpr (Ledger)
            for (const Share& t : shares_) dissipated_ += t.lost, wall_work_ += t.wall_power * dt;
    }
    // Throws naming the step when the totals are not finite (checked after the forces, which name
    // the contact).
    void check_finite(std::size_t step, double time) const {
        if (Ledger && !std::isfinite(dissipated_.total() + wall_work_))
            throw std::runtime_error("non-finite energy ledger at step " + std::to_string(step) + " (t = " + std::to_string(time) +
                                     " s): a contact law booked a non-finite loss");
    }
    // Energy a removed wall's contacts held leaves with it, booked as work the wall took away.
    void wall_took(double energy) { wall_work_ -= energy; }

    const Dissipation& dissipated() const { return dissipated_; }
    double wall_work() const { return wall_work_; }

    void write(CheckpointWriter& w) const { w.value(dissipated_), w.value(wall_work_); }
    void read(CheckpointReader& r) { r.value(dissipated_), r.value(wall_work_); }

private:
    std::vector<Share> shares_;
    Dissipation dissipated_;  // so far, J
    double wall_work_ = 0;    // J done by walls on particles so far
};

}  // namespace demscale::dem
