// Critical time steps of a scene. Rayleigh time T_R = π R √(ρ/G) / (0.1631 ν + 0.8766) (EDEM docs,
// docs/model.md §6) and the Hertz contact duration T_H = 2.87 (m*² / (R* E*² v))^(1/5) (elastic impact
// at speed v; Johnson 1985). demscale takes dt ≤ 0.2 T_R as safe. SI units.
#pragma once

#include <string>

#include "dem/material.hpp"

namespace demscale::dem {

double rayleigh_time(const Material& m, double radius);
double hertz_contact_time(double e_star, double r_eff, double m_eff, double impact_speed);
// Linear spring–dashpot contact duration π / √(k/m* − (c/2m*)²).
double linear_contact_time(double k, double m_eff, double restitution);

// Throws InputError naming the step and the limit when dt > safety·critical, unless forced.
// field: where dt came from, for the message (e.g. "scene.toml:40: run.dt_s").
// what: the time scale's name ("the Rayleigh time").
void check_time_step(double dt, double critical, double safety, bool force, const std::string& field = "dt",
                     const std::string& what = "the Rayleigh time");

}  // namespace demscale::dem
