#include "dem/time_step.hpp"

#include <cmath>
#include <numbers>

#include "core/input_error.hpp"

namespace demscale::dem {

double rayleigh_time(const Material& m, double radius) {
    const double g = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
    return std::numbers::pi * radius * std::sqrt(m.density / g) / (0.1631 * m.poisson_ratio + 0.8766);
}

double hertz_contact_time(double e_star, double r_eff, double m_eff, double v) {
    return 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * v), 0.2);
}

double linear_contact_time(double k, double m_eff, double e) {
    const double beta = damping_ratio(e);
    const double w0 = std::sqrt(k / m_eff);
    return std::numbers::pi / (w0 * std::sqrt(1.0 - beta * beta));
}

void check_time_step(double dt, double critical, double safety, bool force, const std::string& field, const std::string& what) {
    require_positive(dt, field);
    if (dt > safety * critical && !force)
        throw InputError(field, format_number(dt) + " s",
                         "<= " + format_short(safety * critical, 3) + " s (" + format_number(safety) +
                             " x " + what + " " + format_short(critical, 3) + " s); pass --force-dt to override");
}

}  // namespace demscale::dem
