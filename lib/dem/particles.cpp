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
    auto cat = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
    cat(position, o.position), cat(velocity, o.velocity), cat(angular_velocity, o.angular_velocity), cat(force, o.force);
    cat(torque, o.torque), cat(radius, o.radius), cat(mass, o.mass), cat(inertia, o.inertia), cat(species, o.species);
    cat(fixed, o.fixed);
}

Particles Particles::mobile() const {
    Particles m;
    for (std::size_t i = 0; i < size(); ++i) {
        if (fixed[i]) continue;
        m.position.push_back(position[i]), m.velocity.push_back(velocity[i]), m.angular_velocity.push_back(angular_velocity[i]);
        m.force.push_back(force[i]), m.torque.push_back(torque[i]), m.radius.push_back(radius[i]), m.mass.push_back(mass[i]);
        m.inertia.push_back(inertia[i]), m.species.push_back(species[i]), m.fixed.push_back(0);
    }
    return m;
}

std::size_t Particles::mobile_count() const {
    return size() - static_cast<std::size_t>(std::count(fixed.begin(), fixed.end(), std::uint8_t{1}));
}

}  // namespace demscale::dem
