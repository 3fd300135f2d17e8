// Exact pendular liquid bridge between two equal spheres: the Young–Laplace equation for an
// axisymmetric meniscus without gravity, solved numerically (Lian, Thornton & Adams 1993;
// Willett et al. 2000 solve the same problem). Lengths in units of the sphere radius R.
//
// Meridian r(s), z(s), tangent angle φ to the axis, arc length s, from the neck (z = 0):
//   dr/ds = sin φ,  dz/ds = cos φ,  dφ/ds = cos φ / r − κ,   κ = Δp·R/γ (mean curvature ×2).
// Boundary conditions: φ = 0 at the neck; at the contact line r = sin β, z = 1 + d − cos β
// (β filling angle, d = ĥ/2 half gap) with φ = π/2 − β − θ. First integral (axial force):
//   F/(2πRγ) = r cos φ − κ r²/2 = const  (neck: r₀ − κr₀²/2; contact line: sin β sin(β+θ) − κ sin²β/2).
// Method: for a neck radius r₀ and β, κ follows from the first integral; the ODE is integrated with
// GSL odeiv2 (rk8pd, adaptive) to r = sin β, giving d(β, r₀) and V(β, r₀). For fixed V̂ the
// solutions form a family in r₀; rupture is its largest d (a fold), found with GSL's Brent
// minimiser; the stable bridge at a given gap is the root of d(r₀) = ĥ/2 on the wide-neck branch.
// Scope: concave necks (r₀ < sin β, β + θ < π/2), the pendular bridges of wet granular DEM.
#pragma once

#include <optional>
#include <string>

#include "core/contact_angle.hpp"

namespace demscale::bridge {

struct YoungLaplaceTolerance {
    double ode = 1e-12;    // GSL odeiv2 absolute and relative error per step
    double root = 1e-12;   // root finding on β and r₀ (relative)
};

// One bridge shape in units of R.
// Sphere–plane (YoungLaplaceBridge::sphere_plane): the sphere above a flat plate at gap ĥ. The
// meridian below the neck is the mirror image of the one above it (the ODE is symmetric about the
// neck), so one integration from the neck up to φ = π/2 − θ_plate gives the plate's footprint and
// how far below the neck the plate lies; with θ_plate = 90° the plate is the mid-plane of two
// equal spheres (V̂/2, ĥ/2).
struct BridgeShape {
    double neck_radius = 0;     // r₀
    double filling_angle = 0;   // β, rad
    double curvature = 0;       // κ = ΔpR/γ (negative: suction)
    double half_gap = 0;        // d = ĥ/2; sphere–plane: the gap ĥ itself
    double volume = 0;          // V̂ = V/R³
    double fhat_neck = 0;       // F/(2πRγ) from the neck ("gorge" method)
    double fhat_contact = 0;    // F/(2πRγ) at the sphere's contact line, with the integrated angle
    double contact_angle_error = 0;  // |φ_end − (π/2 − β − θ)|, rad: a check of the integration
    // Sphere–plane only (0 otherwise):
    double plate_radius = 0;    // the footprint on the plate, r_p
    double fhat_plate = 0;      // F/(2πRγ) at the plate's contact line, with the integrated angle
    double meniscus_area = 0;   // liquid–gas area / R²
};

enum class YoungLaplaceStatus { ok, above_rupture, not_converged, outside_scope };

struct YoungLaplaceResult {
    YoungLaplaceStatus status = YoungLaplaceStatus::not_converged;
    std::string message;          // why, when not ok
    BridgeShape shape;            // valid when ok
    double hhat_rupture = 0;      // largest full gap ĥ with a stable bridge (valid unless not_converged)
    bool ok() const { return status == YoungLaplaceStatus::ok; }
};

// The shape for (β, r₀) — one ODE integration. nullopt when the profile never reaches the sphere.
std::optional<BridgeShape> integrate_bridge(double filling_angle, double neck_radius, ContactAngle theta,
                                            const YoungLaplaceTolerance& tol = {});

// The same d and V computed by quadrature of the first integral (GSL QAG), an independent check
// of the ODE integration: returns {half_gap, volume}.
std::pair<double, double> bridge_by_quadrature(double filling_angle, double neck_radius, ContactAngle theta);

// Rupture of a bridge of volume V̂: the fold of the constant-volume family. Also the neck radius there.
struct Rupture {
    double hhat = 0;
    double neck_radius = 0;
    // false: a fold, F − F_c ∝ √(ĥ_c − ĥ); true: the end of a plate's piece (θ_plate > 0), where the
    // force still has a finite slope in the gap.
    bool piece_end = false;
};
std::optional<Rupture> young_laplace_rupture(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol = {});

// Whether the symmetric bridge between equal spheres loses stability to an antisymmetric mode
// (liquid moving to one sphere) before the fold of its family; hhat: where (the fold when it holds).
enum class SymmetryStatus { holds_to_fold, breaks, not_determined };
struct SymmetryCheck {
    SymmetryStatus status = SymmetryStatus::not_determined;
    double hhat = 0;
};

// Bridges of one volume and contact angle: the constant-volume family is traced once (rupture,
// widest neck), then each gap costs one root search. Use it for curves and grids.
class YoungLaplaceBridge {
public:
    // Two equal spheres; with theta_plate, a sphere above a plate (as sphere_plane()).
    YoungLaplaceBridge(double vhat, ContactAngle theta, const YoungLaplaceTolerance& tol = {},
                       std::optional<ContactAngle> theta_plate = std::nullopt);
    // A sphere above a flat plate: V̂ the whole bridge, ĥ the gap to the plate, θ on the sphere,
    // theta_plate on the plate. The force is F/(2πRγ) on the sphere, as between spheres.
    static YoungLaplaceBridge sphere_plane(double vhat, ContactAngle theta, ContactAngle theta_plate,
                                           const YoungLaplaceTolerance& tol = {});

    // Valid when family_ok(); otherwise every solve() reports outside_scope with family_message().
    bool family_ok() const { return rupture_.has_value() && widest_neck_.has_value(); }
    const std::string& family_message() const { return family_message_; }
    // Rupture at the first instability: the fold of the family, or, between spheres, symmetry
    // breaking where it comes first (θ ≳ 25°).
    double hhat_rupture() const;
    double hhat_fold() const { return rupture_ ? rupture_->hhat : 0.0; }
    const SymmetryCheck& symmetry() const { return symmetry_; }  // between spheres; not_determined on a plate
    // The same check with a chosen second residual (the default: by_angle below θ = 20°, where the
    // meniscus meets the sphere almost tangentially; at_sphere above, where near rupture the angle
    // condition can be met early): two routes to one answer, compared in tests.
    enum class Residual { at_sphere, by_angle };
    SymmetryCheck check_symmetry(Residual residual) const;
    // Whether F̂ keeps a finite slope in ĥ at rupture (no fold there): the end of a plate's piece,
    // or symmetry breaking.
    bool rupture_has_slope() const { return (rupture_ && rupture_->piece_end) || symmetry_.status == SymmetryStatus::breaks; }

    // The stable bridge at full gap ĥ ≥ 0. Never a silent number: status says whether a bridge
    // exists (above_rupture: none), and not_converged / outside_scope carry a message.
    YoungLaplaceResult solve(double hhat) const;

private:
    double vhat_;
    ContactAngle theta_;
    YoungLaplaceTolerance tol_;
    std::optional<ContactAngle> plate_;  // the plate's contact angle; nullopt: two equal spheres
    std::optional<Rupture> rupture_;
    std::optional<double> widest_neck_;
    SymmetryCheck symmetry_;
    std::string family_message_;
    YoungLaplaceResult solve_on_family(double hhat) const;  // any gap up to the fold
};

// One-off convenience: YoungLaplaceBridge(vhat, theta, tol).solve(hhat).
YoungLaplaceResult solve_young_laplace(double vhat, ContactAngle theta, double hhat,
                                       const YoungLaplaceTolerance& tol = {});

}  // namespace demscale::bridge
