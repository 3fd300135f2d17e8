#include "similarity/scaling_choice.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/input_error.hpp"

namespace demscale::similarity {

ScaleBasis basis_keeping(double length_factor, std::string_view first, std::string_view second) {
    require_positive(length_factor, "length_factor");
    const Dimension d1 = find_quantity(first, "--keep").dimension;
    const Dimension d2 = find_quantity(second, "--keep").dimension;
    // Unknowns x = (ln S_L, ln S_ρ, ln S_T):  x_0 = ln S_L,  d1·x = 0,  d2·x = 0.
    Eigen::Matrix3d m;
    m << 1, 0, 0, d1.length, d1.density, d1.time, d2.length, d2.density, d2.time;
    const Eigen::Vector3d rhs(std::log(length_factor), 0, 0);
    Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
    if (lu.rank() < 3)
        throw InputError("--keep", std::string(first) + "," + std::string(second),
                         "two quantities that together with length fix the density and time scales "
                         "(e.g. gravity,density)");
    const Eigen::Vector3d x = lu.solve(rhs);
    return {std::exp(x[0]), std::exp(x[1]), std::exp(x[2])};
}

std::vector<QuantityScaling> evaluate_scaling(const ScalingChoice& choice) {
    // Named as the user gives them (demscale scaling --length/--density/--time/--hold).
    require_positive(choice.basis.length, "--length");
    require_positive(choice.basis.density, "--density");
    require_positive(choice.basis.time, "--time");
    for (const std::string& key : choice.held) find_quantity(key, "--hold");  // validates the names

    std::vector<QuantityScaling> rows;
    for (const Quantity& q : quantity_catalogue()) {
        QuantityScaling s;
        s.quantity = &q;
        s.required = scale_factor(q.dimension, choice.basis);
        s.held = std::find(choice.held.begin(), choice.held.end(), q.key) != choice.held.end();
        s.applied = s.held ? 1.0 : s.required;
        s.broken = s.held && std::abs(std::log(s.required)) > 1e-12;
        rows.push_back(s);
    }
    return rows;
}

}  // namespace demscale::similarity
