// How dear it is for two threads to share data on this machine now: the time a cache line takes
// when each of two threads updates lines the other wrote the round before (every line crosses
// between the cores), against lines each keeps on its own core, and an empty OpenMP region. On
// the project's virtual 2-core machine the crossing cost flips between about 1.3 and 5-7 ns a line
// from one minute to the next, and the engine's 2-thread speed-up with it (docs/performance.md):
// the benchmark scripts log it beside each run. A timing, not a physical quantity.
#pragma once

#include <optional>

namespace demscale {

struct CoreLink {
    double kept_ns;      // per line, each thread its own lines
    double crossing_ns;  // per line, each line last written by the other thread
    double region_us;    // one empty parallel region of two threads
};

// About a tenth of a second on two threads; none when OpenMP cannot run two threads here.
std::optional<CoreLink> measure_core_link();

}  // namespace demscale
