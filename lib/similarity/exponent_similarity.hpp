// What a candidate surface-tension exponent k (γ̄ = γ·S_f^k, Yun & Park 2017 Eq. 12) means under
// the similarity algebra of Feng et al. (2009): particle replacement fixes S_L = S_f and S_ρ = 1,
// so k fixes the time scale S_T = S_f^t through γ's dimension ρ L³ T⁻² (t = (3 − k)/2). Each
// similarity group of the slump test then scales by a power of S_f; exponent 0 means "kept".
#pragma once

#include <string>
#include <vector>

#include "similarity/dimension.hpp"

namespace demscale::similarity {

struct ExponentGroup {
    std::string name;         // what the group compares
    double sf_exponent = 0;   // the group scales by S_f^sf_exponent under replacement
    bool kept() const;        // |sf_exponent| < 1e-12
};

struct HeldQuantity {
    std::string key;          // catalogue key (gravity, youngs_modulus, velocity, viscosity)
    std::string what;         // as a person says it
    double demanded_exponent; // the implied basis demands a factor S_f^this; held at 1
};

struct ExponentSimilarity {
    double exponent = 0;       // k
    double time_exponent = 0;  // S_T = S_f^t implied by k (S_L = S_f, S_ρ = 1)
    std::vector<ExponentGroup> groups;
    std::vector<HeldQuantity> held;  // parameters a slump scene keeps physical
};

ExponentSimilarity exponent_similarity(double k);

// Catalogue keys whose value a coarse slump scene may scale by the implied basis instead of holding.
const std::vector<std::string>& scalable_parameters();

// S_f exponent the basis implied by k demands of a catalogue quantity (throws InputError naming
// `field` for an unknown key).
double demanded_exponent(const std::string& key, double k, const std::string& field);
// The same for a quantity of dimension d: S_f^e keeps it similar under the basis k implies.
double demanded_exponent(Dimension d, double k);

}  // namespace demscale::similarity
