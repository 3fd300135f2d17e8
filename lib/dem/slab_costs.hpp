// What the threads' slabs of space cost, measured, for the next draw of the slabs (pair_shares.hpp).
// The slabs are drawn by a model of the work (a pair that acts weighs acting_cost pairs passed
// over, a sphere's walls their tests, work_split.hpp); the model misses by about 5-10 % of a step
// in either direction from one draw to the next (a slab's face, a pile's spreading front, the
// cache), and at the barrier after the loop one thread then waits for the other
// (docs/performance.md). Each draw records where its slabs lie and what they weighed; the engine
// adds the seconds each slab's thread took; the next draw weighs what lies in each old slab by
// that slab's seconds per weight over the mean, so the slabs follow the measured cost. The cuts
// move, never what a pair computes: the same bits for any draw.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace demscale::dem {

struct SlabCosts {
    int axis = -1;                        // the axis the slabs cut (0 x, 1 y, 2 z)
    std::vector<double> cuts;             // m along it, ascending: slab t lies between cuts[t - 1] and cuts[t]
    std::vector<double> weight;           // each slab's modelled weight (work_split.hpp units)
    std::vector<std::vector<double>> took;  // each slab's thread's seconds, step by step since the draw

    void took_step(std::size_t slab, double seconds) {
        if (slab < took.size()) took[slab].push_back(seconds);
    }

    // Per slab, what the next draw multiplies the weight lying in it by: its median step's seconds
    // per weight over the mean of those (the median: a step in which the host took the core away
    // from one thread says nothing of the slab's cost). Empty without a measurement of `parts`
    // slabs along `along`; within [1/2, 2], so that an odd window moves a cut by a bounded amount.
    std::vector<double> factors(int parts, int along) const {
        if (along != axis || static_cast<int>(weight.size()) != parts || took.size() != weight.size()) return {};
        std::vector<double> rate(weight.size());
        double mean = 0;
        for (std::size_t t = 0; t < rate.size(); ++t) {
            std::vector<double> steps = took[t];
            if (steps.empty() || !(weight[t] > 0)) return {};
            std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
            if (!(steps[steps.size() / 2] > 0)) return {};  // no time read: no measurement
            rate[t] = steps[steps.size() / 2] / weight[t];
            mean += rate[t] / static_cast<double>(rate.size());
        }
        if (!(mean > 0)) return {};
        for (double& r : rate) r = std::clamp(r / mean, 0.5, 2.0);
        return rate;
    }

    // The slab at x, m along `axis`.
    std::size_t slab_at(double x) const {
        return static_cast<std::size_t>(std::upper_bound(cuts.begin(), cuts.end(), x) - cuts.begin());
    }
};

}  // namespace demscale::dem
