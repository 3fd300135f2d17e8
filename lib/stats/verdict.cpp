#include "stats/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_cdf.h>

namespace demscale::stats {

std::string verdict_name(Verdict v) {
    switch (v) {
        case Verdict::pass: return "PASS";
        case Verdict::fail: return "FAIL";
        case Verdict::inconclusive: break;
    }
    return "INCONCLUSIVE";
}

Verdict equivalence_verdict(const Interval& d, double tolerance) {
    if (d.low >= -tolerance && d.high <= tolerance) return Verdict::pass;
    if (d.low > tolerance || d.high < -tolerance) return Verdict::fail;
    return Verdict::inconclusive;
}

double smallest_confirmable_tolerance(const Interval& d) { return std::max(std::abs(d.low), std::abs(d.high)); }

Verdict combine(const std::vector<Verdict>& verdicts) {
    Verdict worst = Verdict::pass;
    for (auto v : verdicts) worst = std::max(worst, v);  // pass < inconclusive < fail
    return worst;
}

bool fails_in_family(double estimate, const Interval& ci, double tolerance, std::size_t m) {
    const double r = m <= 1 ? 1.0 : gsl_cdf_ugaussian_Pinv(1 - 0.025 / static_cast<double>(m)) / gsl_cdf_ugaussian_Pinv(0.975);
    const Interval wide{estimate - (estimate - ci.low) * r, estimate + (ci.high - estimate) * r};
    return equivalence_verdict(wide, tolerance) == Verdict::fail;
}

}  // namespace demscale::stats
