// Simplified JKR adhesion (the cohesion slot; docs/models/adhesion-sjkr.md): while two surfaces
// overlap, an attraction F = k_c·A along −n, k_c the cohesion energy density (J/m³) and A = π a² the
// area of the circle where the undeformed surfaces cut each other (LIGGGHTS' `cohesion sjkr`):
//   sphere–sphere a² = R δ − δ²/4 (exact for equal radii R; R = the pair's harmonic-mean radius
//   otherwise, exact to first order in δ), sphere–wall a² = δ (2R − δ).
// No force across a gap, no history; conservative: U = −∫ k_c A dδ: −k_cπ(R δ²/2 − δ³/12) between
// spheres, −k_cπ(R δ² − δ³/3) at a wall. Acts in dry scenes (in a wet one the bridge is the
// cohesion). The Coulomb limit of the tangential spring sees the contact force without it. SI.
#pragma once

#include <numbers>

#include "dem/contact_pair.hpp"
#include "dem/law_part.hpp"

namespace demscale::dem {

struct CohesionSjkr {
    struct State {};
    template <class Lost>
    using StateFor = State;
    double energy_density;  // k_c, J/m³

    static CohesionSjkr build(const ContactSettings& s, const LawSizes&, const std::string&) { return {s.cohesion_energy_density}; }
    double range() const { return 0.0; }
    bool holds(const State&) const { return false; }
    bool needs_gap_velocity() const { return false; }

    // Attraction (N, along −n on i) at overlap δ (m) with a sphere (r: the pair's harmonic-mean
    // radius, m) or a wall (r: the sphere's radius); nothing is dissipated.
    template <class Lost>
    DEMSCALE_HOT double pull(double overlap, double r, double, double, bool with_wall, State&, Lost&) const {
        if (overlap <= 0) return 0.0;
        const double a2 = with_wall ? overlap * (2 * r - overlap) : overlap * (r - 0.25 * overlap);
        return energy_density * std::numbers::pi * a2;
    }
    template <class Lost>
    Vec3 drag(double, double, const Vec3&, double, bool, const State&, Lost&) const { return Vec3::Zero(); }

    // U(δ) ≤ 0, J: the work the attraction did since the surfaces met.
    double stored_energy(const ContactPair& c, const State&) const {
        const double d = c.overlap, r = c.r_harmonic;
        if (d <= 0) return 0.0;
        return -energy_density * std::numbers::pi * (c.wall ? r * d * d - d * d * d / 3 : 0.5 * r * d * d - d * d * d / 12);
    }
};

// k_c is an energy per volume, a stress (ρ L² T⁻², like E): kept, or scaled by
// --scale cohesion_energy_density.
inline constexpr Parameter sjkr_parameters[] = {
    {"contact.cohesion_energy_density_j_per_m3", "cohesion energy density k_c (SJKR)", "J/m^3", {2, 1, -2}, 0, {0, unbounded, false},
     Replacement::scalable, "cohesion_energy_density", "cohesionEnergyDensity", LiggghtsKind::per_type_pair,
     [](const ContactSettings& s) { return s.cohesion_energy_density; },
     [](ContactSettings& s, double x) { s.cohesion_energy_density = x; }},
};

// Its attraction only softens the contact (by k_cπR per unit overlap): the Hertz limit still holds,
// no time scale of its own.
inline constexpr LawPart sjkr_part{
    "simplified JKR adhesion (SJKR)", sjkr_parameters, [](const ContactSettings& s) { return !s.wet && s.cohesion_energy_density > 0; },
    nullptr, {}, "cohesion sjkr", "tangential_reduce on",
    [](const ContactSettings& s) { return !s.wet || s.cohesion_energy_density == 0; },
    "0 in a wet scene (its liquid bridges are the cohesion; liquid.wet = false for a dry adhesive powder)",
    Slot::cohesion, "sjkr",
    [](ContactSettings& s) {  // chosen by any k_c > 0 in a dry scene: 10⁴ J/m³ where it had none
        s.wet = false;
        if (s.cohesion_energy_density == 0) s.cohesion_energy_density = 1e4;
    }};

}  // namespace demscale::dem
