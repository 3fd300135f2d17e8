#include "bridge/bridge_cost.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

namespace demscale::bridge {

namespace {
// Wall time of n calls in seconds, gaps cycling over [0, ĥ_c].
double time_calls(const BridgeModel& model, double vhat, ContactAngle theta, double hc, long n, double& checksum) {
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < n; ++i) checksum += model.fhat(vhat, theta, hc * static_cast<double>(i % 97) / 97.0);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

EvaluationCost measure_evaluation_cost(const BridgeModel& model, double vhat, ContactAngle theta, double seconds_per_run,
                                       int repeats) {
    const double hc = model.hhat_rupture(vhat, theta);  // also warms the per-pair cache
    EvaluationCost cost;
    long n = 1;
    double elapsed = 0;
    while ((elapsed = time_calls(model, vhat, theta, hc, n, cost.checksum)) < 0.01 * seconds_per_run && n < (1L << 40)) n *= 4;
    cost.evaluations_per_run = std::max(1L, static_cast<long>(static_cast<double>(n) * seconds_per_run / elapsed));
    std::vector<double> ns;
    for (int r = 0; r < repeats; ++r)
        ns.push_back(1e9 * time_calls(model, vhat, theta, hc, cost.evaluations_per_run, cost.checksum) /
                     static_cast<double>(cost.evaluations_per_run));
    std::nth_element(ns.begin(), ns.begin() + repeats / 2, ns.end());
    cost.ns_per_evaluation = ns[repeats / 2];
    return cost;
}

}  // namespace demscale::bridge
