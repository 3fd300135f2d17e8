#include "core/input_error.hpp"

#include <cmath>
#include <cstdio>

namespace demscale {

InputError::InputError(std::string field, std::string value, std::string accepted)
    : std::runtime_error(field + " = " + value + ": accepted " + accepted),
      field_(std::move(field)), value_(std::move(value)), accepted_(std::move(accepted)) {}

std::string format_number(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[32];
    for (int digits = 6; digits <= 17; ++digits) {  // shortest form that reads back exactly
        std::snprintf(buf, sizeof buf, "%.*g", digits, x);
        if (std::strtod(buf, nullptr) == x) break;
    }
    return buf;
}

std::string format_short(double x, int digits) {
    if (!std::isfinite(x)) return format_number(x);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

void require_finite(double x, const std::string& field) {
    if (!std::isfinite(x)) throw InputError(field, format_number(x), "a finite number");
}

void require_positive(double x, const std::string& field) {
    if (!(std::isfinite(x) && x > 0.0)) throw InputError(field, format_number(x), "a finite number > 0");
}

void require_in_open_interval(double x, double lo, double hi, const std::string& field) {
    if (!(std::isfinite(x) && x > lo && x < hi))
        throw InputError(field, format_number(x), "(" + format_number(lo) + ", " + format_number(hi) + ")");
}

}  // namespace demscale
