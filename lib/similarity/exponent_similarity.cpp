#include "similarity/exponent_similarity.hpp"

#include <cmath>
#include <utility>

#include "similarity/quantity_catalogue.hpp"
#include "similarity/stress_similarity.hpp"

namespace demscale::similarity {

namespace {

Dimension dim(std::string_view key, const std::string& field) { return find_quantity(key, field).dimension; }

// Solve replacement_exponent(surface tension, t) = k for t: linear in t.
double implied_time_exponent(double k) {
    const Dimension gamma = dim("surface_tension", "surface_tension");
    const double at0 = replacement_exponent(gamma, 0.0), slope = replacement_exponent(gamma, 1.0) - at0;
    const double t = (k - at0) / slope;
    return t == 0 ? 0.0 : t;  // no "-0" in tables
}

// The parameters a slump scene holds physical unless told to scale them: key, and how a person says it.
const std::pair<std::string, std::string> held_parameters[] = {
    {"gravity", "gravitational acceleration g"}, {"youngs_modulus", "Young's modulus E"}, {"velocity", "lift speed"},
    {"viscosity", "liquid viscosity mu (viscous bridge)"}};

}  // namespace

bool ExponentGroup::kept() const { return std::abs(sf_exponent) < 1e-12; }

const std::vector<std::string>& scalable_parameters() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> k;
        for (const auto& held : held_parameters) k.push_back(held.first);
        return k;
    }();
    return keys;
}

double demanded_exponent(const std::string& key, double k, const std::string& field) {
    return demanded_exponent(dim(key, field), k);
}

double demanded_exponent(Dimension d, double k) { return replacement_exponent(d, implied_time_exponent(k)); }

ExponentSimilarity exponent_similarity(double k) {
    ExponentSimilarity s;
    s.exponent = k;
    s.time_exponent = implied_time_exponent(k);
    // Ratios of the capillary force to the forces of the algebra's groups, then the Froude numbers:
    // the lift speed, g and the cone are held, so only the particle-scale one changes (as 1/R̄).
    for (const auto& g : bridge_similarity_groups()) s.groups.push_back({g.name, group_ratio_exponent(g, k)});
    s.groups.push_back({"particle Froude number v^2/(g R), v and g held", -1});
    s.groups.push_back({"pile Froude number v^2/(g H), cone held", 0});
    for (const auto& [key, what] : held_parameters) s.held.push_back({key, what, demanded_exponent(key, k, key)});
    return s;
}

}  // namespace demscale::similarity
