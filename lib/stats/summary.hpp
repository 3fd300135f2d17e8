// Statistics of an ensemble of runs (seeds): mean, sample standard deviation and a 95 % confidence
// interval of the mean, and of the difference of two ensembles' means. Student t intervals
// (Welch–Satterthwaite degrees of freedom for a difference): the seeds' results are independent,
// and the t interval is exact for normal data and close for the few-seed ensembles used here.
// Quantities are dimensionless or in whatever unit the caller passes.
#pragma once

#include <cstddef>
#include <vector>

namespace demscale::stats {

struct Interval {
    double low = 0, high = 0;
    bool contains(double x) const { return low <= x && x <= high; }
    double half_width() const { return 0.5 * (high - low); }
};

struct Summary {
    std::size_t n = 0;
    double mean = 0, sd = 0;  // sd: sample standard deviation (n − 1); 0 for n < 2
    Interval ci;              // 95 % Student t interval of the mean; [mean, mean] for n < 2
};

// Two-sided Student t quantile t_{1 − α/2, ν} (GSL), ν > 0 (need not be an integer).
double student_t_quantile(double confidence, double dof);

Summary summarize(const std::vector<double>& x, double confidence = 0.95);

// The middle value (of an even count, the upper of the two middle ones); 0 for no values.
double median(std::vector<double> x);

// Interval of mean(b) − mean(a) (Welch); empty samples or n < 2 on both sides: a zero-width interval
// at the difference of the means.
Interval difference_interval(const std::vector<double>& a, const std::vector<double>& b, double confidence = 0.95);

}  // namespace demscale::stats
