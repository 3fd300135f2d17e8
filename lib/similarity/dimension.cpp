#include "similarity/dimension.hpp"

#include <cmath>

namespace demscale::similarity {

double scale_factor(Dimension d, ScaleBasis s) {
    return std::exp(d.length * std::log(s.length) + d.density * std::log(s.density) +
                    d.time * std::log(s.time));
}

}  // namespace demscale::similarity
