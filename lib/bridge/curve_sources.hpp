// Every source a scene's DEM bridges can take their curve from (liquid.bridge_variant between
// spheres, liquid.wall_bridge to the walls), each declaring what a scene's choice needs: the value
// a scene writes, the geometries it has, the V̂ it holds for, how its curve is built at the scene's
// V̂ and θ, its words in a LIGGGHTS deck (or none, said in the deck), its row in the report and its
// line in the run-cache key. The scene reader, the cache key, the report, the export and the law's
// builder all read this one list (docs/adding-a-contact-law.md). Adding a source: one entry in
// curve_sources.cpp (and its value in CurveSource).
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "bridge/bridge_curve.hpp"
#include "bridge/mikami_variant.hpp"

namespace demscale::bridge {

struct CurveSourceEntry {
    std::string_view value;  // what a scene writes: "mikami1998", "table"
    CurveSource source;
    MikamiVariant fit_variant = MikamiVariant::mikami1998;  // a fit's printed form (source fit)
    std::string_view label;  // the report's row: what the bridges follow
    bool sphere_sphere = true, sphere_wall = false;
    double vhat_min = 0, vhat_max = 0;  // V̂ = V/R³ where it holds: a wet scene outside is refused
    std::string_view vhat_range_name;   // "Mikami's fitted range"
    // Its curve at V̂ and θ for a geometry it has; `fit`: the scene's Mikami options (printed form,
    // rupture law). Throws std::runtime_error where it has no bridge.
    BridgeCurve (*build)(double vhat, ContactAngle theta, BridgeGeometry geometry, const MikamiOptions& fit) = nullptr;
    std::string_view liggghts;    // LIGGGHTS' own words for it; empty: no equivalent (the deck says so)
    std::string_view cache_name;  // its cache-key line particle_curve_NAME / wall_curve_NAME; empty: a fit (no line)
    bool has(BridgeGeometry g) const { return g == BridgeGeometry::sphere_sphere ? sphere_sphere : sphere_wall; }
};

std::span<const CurveSourceEntry> curve_sources();

// The entry of a scene's choice (a fit: the entry of its printed form).
const CurveSourceEntry& curve_source(CurveSource source, MikamiVariant fit_variant, BridgeGeometry geometry);

// The entry a scene's value names for this geometry; nullptr if none.
const CurveSourceEntry* find_curve_source(std::string_view value, BridgeGeometry geometry);

// "mikami1998, yun-park-2017, table": the values a scene may write for this geometry.
std::string curve_source_values(BridgeGeometry geometry);

}  // namespace demscale::bridge
