#include "dem/particles.hpp"

#include <algorithm>
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
    fixed.push_back(0);
    return size() - 1;
}

std::size_t Particles::add_fixed(const Vec3& x, double r, double rho, int species_id) {
    const std::size_t i = add(x, r, rho, Vec3::Zero(), species_id);
    fixed[i] = 1;
    return i;
}

void Particles::append(const Particles& o) {
    for_each_array([&](auto member) { (this->*member).insert((this->*member).end(), (o.*member).begin(), (o.*member).end()); });
}

Particles Particles::mobile() const {
    std::vector<std::uint32_t> keep;
    for (std::uint32_t i = 0; i < size(); ++i)
        if (!fixed[i]) keep.push_back(i);
    Particles m = *this;
    m.reorder(keep);
    return m;
}

void Particles::reorder(const std::vector<std::uint32_t>& order) {
    for_each_array([&](auto member) { gather(this->*member, order); });
}

std::size_t Particles::mobile_count() const {
    return size() - static_cast<std::size_t>(std::count(fixed.begin(), fixed.end(), std::uint8_t{1}));
}

}  // namespace demscale::dem
