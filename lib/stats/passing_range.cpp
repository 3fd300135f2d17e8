#include "stats/passing_range.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace demscale::stats {

PassingRange passing_range(const TransitionFit& fit, double sf, double log_gamma, double tolerance, Interval fine_range) {
    if (!(sf > 1) || !(tolerance > 0)) throw std::invalid_argument("passing_range: S_f > 1 and a positive tolerance");
    const double ls = std::log(sf), at = mean_response(fit, log_gamma), step = 0.005;
    // From δ = 0 outward in steps of 0.005 in k, until the tolerance or the end of the fine levels.
    auto end = [&](double dir, bool& open) {
        double delta = 0;
        for (;;) {
            const double next = delta + dir * step, u = log_gamma + next * ls;
            if (u < fine_range.low || u > fine_range.high || std::abs(next) > 20) return open = true, delta;
            if (std::abs(mean_response(fit, u) - at) > tolerance) return delta;
            delta = next;
        }
    };
    PassingRange r;
    r.sf = sf;
    const double lo = end(-1, r.low_open), hi = end(+1, r.high_open);
    r.at_k_hat = {fit.k + lo, fit.k + hi};
    r.over_interval = {fit.ci.high + lo, fit.ci.low + hi};
    return r;
}

std::vector<PassingRange> passing_ranges(const std::vector<TransitionFit>& fits, const std::vector<double>& sfs, double log_gamma,
                                         double tolerance, Interval fine_range) {
    std::vector<PassingRange> out;
    for (std::size_t i = 0; i < sfs.size(); ++i) out.push_back(passing_range(fits.at(i), sfs[i], log_gamma, tolerance, fine_range));
    if (sfs.size() > 1) {
        PassingRange joint;
        joint.at_k_hat = joint.over_interval = {-INFINITY, INFINITY};
        for (double sf : sfs) {
            const PassingRange one = passing_range(fits.back(), sf, log_gamma, tolerance, fine_range);
            auto narrow = [](Interval& a, const Interval& b) { a = {std::max(a.low, b.low), std::min(a.high, b.high)}; };
            if (one.at_k_hat.low >= joint.at_k_hat.low) joint.low_open = one.low_open;
            if (one.at_k_hat.high <= joint.at_k_hat.high) joint.high_open = one.high_open;
            narrow(joint.at_k_hat, one.at_k_hat);
            narrow(joint.over_interval, one.over_interval);
        }
        out.push_back(joint);
    }
    return out;
}

}  // namespace demscale::stats
