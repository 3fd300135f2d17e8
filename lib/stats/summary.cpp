#include "stats/summary.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_cdf.h>
#include <numeric>

namespace demscale::stats {

double student_t_quantile(double confidence, double dof) { return gsl_cdf_tdist_Pinv(0.5 + 0.5 * confidence, dof); }

namespace {
double mean_of(const std::vector<double>& x) { return x.empty() ? 0 : std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size()); }
double variance_of(const std::vector<double>& x, double mean) {
    if (x.size() < 2) return 0;
    double s = 0;
    for (double v : x) s += (v - mean) * (v - mean);
    return s / static_cast<double>(x.size() - 1);
}
}  // namespace

Summary summarize(const std::vector<double>& x, double confidence) {
    Summary s;
    s.n = x.size();
    s.mean = mean_of(x);
    s.sd = std::sqrt(variance_of(x, s.mean));
    s.ci = {s.mean, s.mean};
    if (s.n >= 2) {
        const double h = student_t_quantile(confidence, static_cast<double>(s.n - 1)) * s.sd / std::sqrt(static_cast<double>(s.n));
        s.ci = {s.mean - h, s.mean + h};
    }
    return s;
}

Interval difference_interval(const std::vector<double>& a, const std::vector<double>& b, double confidence) {
    const double ma = mean_of(a), mb = mean_of(b), d = mb - ma;
    const double va = a.size() >= 2 ? variance_of(a, ma) / static_cast<double>(a.size()) : 0;
    const double vb = b.size() >= 2 ? variance_of(b, mb) / static_cast<double>(b.size()) : 0;
    const double v = va + vb;
    if (!(v > 0)) return {d, d};
    // Welch–Satterthwaite: ν = (va + vb)² / (va²/(na − 1) + vb²/(nb − 1)), terms of a one-run side left out.
    double denom = 0;
    if (a.size() >= 2) denom += va * va / static_cast<double>(a.size() - 1);
    if (b.size() >= 2) denom += vb * vb / static_cast<double>(b.size() - 1);
    const double h = student_t_quantile(confidence, v * v / denom) * std::sqrt(v);
    return {d - h, d + h};
}

double median(std::vector<double> x) {
    if (x.empty()) return 0.0;
    const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
    std::nth_element(x.begin(), mid, x.end());
    return *mid;
}

}  // namespace demscale::stats
