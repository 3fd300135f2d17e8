#include "similarity/quantity_catalogue.hpp"

#include <array>

#include "core/input_error.hpp"
#include "core/nearest_name.hpp"

namespace demscale::similarity {

namespace {
constexpr Dimension L{1, 0, 0}, RHO{0, 1, 0}, T{0, 0, 1}, ONE{0, 0, 0};
constexpr Dimension MASS = RHO * L * L * L;
constexpr Dimension VELOCITY = L / T;
constexpr Dimension ACCELERATION = VELOCITY / T;
constexpr Dimension FORCE = MASS * ACCELERATION;
constexpr Dimension AREA = L * L;
constexpr Dimension STRESS = FORCE / AREA;
constexpr Dimension ENERGY = FORCE * L;
constexpr Dimension STIFFNESS = FORCE / L;       // N/m
constexpr Dimension DAMPING = FORCE / VELOCITY;  // N·s/m

constexpr std::array catalogue{
    Quantity{"length", "length, radius, overlap, gap", "m", L},
    Quantity{"area", "area (contact, cross-section)", "m^2", AREA},
    Quantity{"volume", "particle volume", "m^3", L * L * L},
    Quantity{"liquid_volume", "liquid bridge volume", "m^3", L * L * L},
    Quantity{"density", "density", "kg/m^3", RHO},
    Quantity{"mass", "mass", "kg", MASS},
    Quantity{"time", "time", "s", T},
    Quantity{"time_step", "time step, contact duration", "s", T},
    Quantity{"velocity", "velocity", "m/s", VELOCITY},
    Quantity{"angular_velocity", "angular velocity", "rad/s", ONE / T},
    Quantity{"acceleration", "acceleration", "m/s^2", ACCELERATION},
    Quantity{"gravity", "gravitational acceleration g", "m/s^2", ACCELERATION},
    Quantity{"force", "force", "N", FORCE},
    Quantity{"torque", "torque", "N m", ENERGY},
    Quantity{"stress", "stress, pressure", "Pa", STRESS},
    Quantity{"youngs_modulus", "Young's modulus", "Pa", STRESS},
    Quantity{"energy", "energy, work", "J", ENERGY},
    Quantity{"normal_stiffness", "normal spring stiffness k_n", "N/m", STIFFNESS},
    Quantity{"tangential_stiffness", "tangential spring stiffness k_t", "N/m", STIFFNESS},
    Quantity{"damping_coefficient", "viscous damping coefficient", "N s/m", DAMPING},
    Quantity{"surface_tension", "surface tension gamma", "N/m", FORCE / L},
    Quantity{"viscosity", "dynamic viscosity", "Pa s", STRESS * T},
    Quantity{"moment_of_inertia", "moment of inertia", "kg m^2", MASS * AREA},
    Quantity{"friction_coefficient", "friction coefficient", "1", ONE},
    Quantity{"restitution", "coefficient of restitution", "1", ONE},
    Quantity{"poisson_ratio", "Poisson's ratio", "1", ONE},
    Quantity{"contact_angle", "contact angle", "rad", ONE},
    Quantity{"moisture_content", "moisture content", "1", ONE},
};
}  // namespace

std::span<const Quantity> quantity_catalogue() { return catalogue; }

std::string_view nearest_quantity_key(std::string_view key) {
    std::array<std::string_view, catalogue.size()> keys;
    for (std::size_t i = 0; i < catalogue.size(); ++i) keys[i] = catalogue[i].key;
    return nearest_name(key, keys);
}

const Quantity& find_quantity(std::string_view key, const std::string& field) {
    for (const Quantity& q : catalogue)
        if (q.key == key) return q;
    throw InputError(field, "\"" + std::string(key) + "\"",
                     "a quantity of the catalogue (did you mean " + std::string(nearest_quantity_key(key)) +
                         "? `demscale scaling --list` shows all)");
}

}  // namespace demscale::similarity
