#include "dem/particles.hpp"

#include <numbers>

#include "core/input_error.hpp"

namespace demscale::dem {

std::size_t Particles::add(const Vec3& x, double r, double rho, const Vec3& v, int species_id) {
    require_positive(r, "particle radius");
    require_positive(rho, "particle density");
    for (int k = 0; k < 3; ++k) require_finite(x[k], "particle position"), require_finite(v[k], "particle velocity");
    const double m = rho * 4.0 / 3.0 * std::numbers::pi * r * r * r;
    position.push_back(x);
    velocity.push_back(v);
    angular_velocity.push_back(Vec3::Zero());
    force.push_back(Vec3::Zero());
    torque.push_back(Vec3::Zero());
    radius.push_back(r);
    mass.push_back(m);
    inertia.push_back(0.4 * m * r * r);
    species.push_back(species_id);
    return size() - 1;
}

}  // namespace demscale::dem
