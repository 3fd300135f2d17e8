// Spheres stored as structure of arrays: one contiguous array per quantity, SI units.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstddef>
#include <vector>

namespace demscale::dem {

using Vec3 = Eigen::Vector3d;

struct Particles {
    std::vector<Vec3> position;          // m
    std::vector<Vec3> velocity;          // m/s
    std::vector<Vec3> angular_velocity;  // rad/s
    std::vector<Vec3> force;             // N, rebuilt every step
    std::vector<Vec3> torque;            // N m, rebuilt every step
    std::vector<double> radius;          // m
    std::vector<double> mass;            // kg
    std::vector<double> inertia;         // kg m², solid sphere 2/5 m r²
    std::vector<int> species;

    std::size_t size() const { return radius.size(); }

    // A solid sphere of density rho (kg/m³). Returns its index.
    std::size_t add(const Vec3& x, double r, double rho, const Vec3& v = Vec3::Zero(), int species_id = 0);
};

}  // namespace demscale::dem
