// Closed-form liquid bridges between equal spheres, for comparison with the exact solution.
//  * Toroidal (circle) meridian: Fisher (1926); Lian, Thornton & Adams (1993). Force by the
//    "gorge" method at the neck; rupture by Lian's (1 + θ/2)·V̂^(1/3).
//  * Willett et al. (2000), Langmuir 16:9396: the full fit (appendix; ln F* = f1 − f2·exp(f3 ln S⁺
//    + f4 ln² S⁺)) and the simple closed form Eq. 12 F* = cos θ/(1 + 2.1 S⁺ + 10 S⁺²), with
//    S⁺ = (ĥ/2)/√V̂ and rupture Eq. 15. F* = F/(2πRγ).
// All in units of R; θ in radians inside.
#pragma once

#include "core/contact_angle.hpp"

namespace demscale::bridge {

struct ToroidalBridge {
    double filling_angle = 0;   // β
    double meridian_radius = 0; // ρ₁
    double neck_radius = 0;     // ρ₂
    double fhat = 0;            // F/(2πRγ) = ρ₂/2 + ρ₂²/(2ρ₁)
};
// The toroidal bridge of volume V̂ at full gap ĥ ≥ 0 (β found by Brent's method); fhat = 0 when
// no circle meridian holds V̂ at that gap.
ToroidalBridge toroidal_bridge(double vhat, ContactAngle theta, double hhat);

// Volume of the toroidal bridge with filling angle β at half gap d (closed form).
double toroidal_volume(double filling_angle, ContactAngle theta, double half_gap);

double willett_full_fhat(double vhat, ContactAngle theta, double hhat);
double willett_simple_fhat(double vhat, ContactAngle theta, double hhat);
double willett_rupture_hhat(double vhat, ContactAngle theta);  // Eq. 15

}  // namespace demscale::bridge
