// The engine's order of its spheres against the input's: when a large scene's spheres are next
// reordered cell by cell (spatial_order.hpp), and where each sphere stood in the input, so that
// what a run reports is in the input's order.
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

#include "dem/checkpoint.hpp"
#include "dem/particles.hpp"
#include "dem/spatial_order.hpp"

namespace demscale::dem {

class SphereOrder {
public:
    SphereOrder(std::size_t spheres, SpatialSort sort) : sort_(sort), input_index_(spheres) {
        std::iota(input_index_.begin(), input_index_.end(), 0u);
    }

    // A reorder is due at the first build and every sort.every_steps steps after it, at those steps
    // exactly (a rebuild is forced then): the order, hence each sphere's pair order, is then the
    // same whatever the skin, which only decides when the list is rebuilt in between.
    bool due(std::size_t spheres, std::size_t steps) const {
        return spheres > 1 && spheres >= sort_.min_particles && (sorts_ == 0 || steps - sorted_at_ >= sort_.every_steps);
    }

    // Takes the new order at step `steps` (order[k]: the sphere to put k-th); returns each
    // sphere's new place (old index → new), for renumbering what refers to it.
    std::vector<std::uint32_t> take(const std::vector<std::uint32_t>& order, std::size_t steps) {
        ++sorts_, sorted_at_ = steps;
        std::vector<std::uint32_t> new_index(order.size()), input(order.size());
        for (std::uint32_t k = 0; k < order.size(); ++k) new_index[order[k]] = k, input[k] = input_index_[order[k]];
        input_index_ = std::move(input);
        return new_index;
    }

    // Where each sphere stood in the input: the engine's sphere k is the input's input_index()[k].
    const std::vector<std::uint32_t>& input_index() const { return input_index_; }
    // The spheres p (in the engine's order) in the input's order (a copy).
    Particles in_input_order(const Particles& p) const {
        std::vector<std::uint32_t> slot(p.size());
        for (std::uint32_t k = 0; k < slot.size(); ++k) slot[input_index_[k]] = k;
        Particles copy = p;
        copy.reorder(slot);
        return copy;
    }
    std::size_t sorts() const { return sorts_; }

    void write(CheckpointWriter& w) const { w.array(input_index_), w.value(sorts_), w.value(sorted_at_); }
    void read(CheckpointReader& r) { r.array(input_index_), r.value(sorts_), r.value(sorted_at_); }

private:
    SpatialSort sort_;
    std::vector<std::uint32_t> input_index_;
    std::size_t sorts_ = 0, sorted_at_ = 0;  // reorders so far; the step of the last
};

}  // namespace demscale::dem
