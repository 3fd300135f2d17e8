// Invalid input: names the field, the offending value and the accepted range,
// so every tool can print one self-explaining line and exit with code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace demscale {

class InputError : public std::runtime_error {
public:
    InputError(std::string field, std::string value, std::string accepted);

    const std::string& field() const { return field_; }
    const std::string& value() const { return value_; }
    const std::string& accepted() const { return accepted_; }

private:
    std::string field_, value_, accepted_;
};

// Formats a double the way error messages and tables show it (shortest round-trip form).
std::string format_number(double x);

// A compact form for labels and prose: `digits` significant digits, no trailing noise.
std::string format_short(double x, int digits = 4);

// Throws InputError unless x is finite and lo < x (open) / lo <= x (closed) etc.
void require_finite(double x, const std::string& field);
void require_positive(double x, const std::string& field);
void require_in_open_interval(double x, double lo, double hi, const std::string& field);

}  // namespace demscale
