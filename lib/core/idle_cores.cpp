#include "core/idle_cores.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace demscale {

int idle_cores(int cores, double load_average) {
    const int busy = std::isfinite(load_average) && load_average > 0 ? static_cast<int>(std::lround(load_average)) : 0;
    return std::clamp(cores - busy, 1, std::max(cores, 1));
}

std::optional<double> load_average() {
    double load = 0;
    if (getloadavg(&load, 1) != 1) return std::nullopt;
    return load;
}

}  // namespace demscale
