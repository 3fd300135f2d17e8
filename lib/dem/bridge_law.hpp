// The liquid-bridge law of wet contact settings, built here and nowhere else: its curves from the
// sources the settings choose (bridge/curve_sources.hpp: liquid.bridge_variant between spheres,
// liquid.wall_bridge to wet walls), its viscous part, one V̂ for every pair. A tabulated curve
// (the exact bridge, Willett's fit) is built once per process for each source, V̂, θ and geometry
// and shared between runs and threads (0.3-0.5 s a column for the exact bridge).
#pragma once

#include <string>

#include "bridge/curve_sources.hpp"
#include "dem/contact_settings.hpp"
#include "dem/laws/cohesion.hpp"

namespace demscale::dem {

// The sources the settings choose, between spheres and to the walls.
const bridge::CurveSourceEntry& particle_curve_source(const ContactSettings& s);
const bridge::CurveSourceEntry& wall_curve_source(const ContactSettings& s);

// A source's curve at V̂ = V/R³ and the settings' θ (and fit options). Throws InputError naming
// `field` (with `where` before it, a file, when given) where the source has no bridge there.
bridge::BridgeCurve bridge_curve(const bridge::CurveSourceEntry& source, const ContactSettings& s, double vhat, bridge::BridgeGeometry geometry,
                                 const std::string& field, const std::string& where = {});

// The law: R = largest_radius_m for every pair (common) or for the range and the pairs of two
// largest spheres (per_pair), the roughness gap of particles of radius_m, V̂ = vhat (m, m, 1).
template <BridgeRadius Radius>
LiquidBridge<Radius> build_liquid_bridge(const ContactSettings& s, double radius_m, double largest_radius_m, double vhat,
                                         const std::string& where = {});

// V̂ = V/R³ of every bridge between particles of radius_m (m): the liquid of Yun & Park's Eq. 5
// from the moisture content and the particle's mass.
double bridge_vhat(const ContactSettings& s, double radius_m);

// The law's builder (dem/law_builder.hpp), LiquidBridge::build: build_liquid_bridge with these
// sizes and V̂ of Eq. 5, for both forms (instantiated in dem/bridge_law.cpp).
extern template CohesionLiquidBridge CohesionLiquidBridge::build(const ContactSettings&, const LawSizes&, const std::string&);
extern template CohesionLiquidBridgePerPair CohesionLiquidBridgePerPair::build(const ContactSettings&, const LawSizes&, const std::string&);

}  // namespace demscale::dem
