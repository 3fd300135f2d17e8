// Dimensions in the basis of Feng et al. (2009) / Feng & Owen (2014): length L, density ρ, time T.
// A quantity of dimension L^a ρ^b T^c scales by S_L^a · S_ρ^b · S_T^c between two systems.
#pragma once

namespace demscale::similarity {

struct Dimension {
    double length = 0;   // exponent of L
    double density = 0;  // exponent of ρ
    double time = 0;     // exponent of T

    friend constexpr Dimension operator*(Dimension x, Dimension y) {
        return {x.length + y.length, x.density + y.density, x.time + y.time};
    }
    friend constexpr Dimension operator/(Dimension x, Dimension y) {
        return {x.length - y.length, x.density - y.density, x.time - y.time};
    }
    friend constexpr bool operator==(Dimension, Dimension) = default;
    constexpr bool dimensionless() const { return length == 0 && density == 0 && time == 0; }
};

// Scale factors of the three basis quantities (model / physical).
struct ScaleBasis {
    double length = 1;   // S_L
    double density = 1;  // S_ρ
    double time = 1;     // S_T
};

// S_L^a · S_ρ^b · S_T^c, computed in log space so large factors do not overflow early.
double scale_factor(Dimension d, ScaleBasis s);

}  // namespace demscale::similarity
