#include "stats/verdict.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace demscale::stats
