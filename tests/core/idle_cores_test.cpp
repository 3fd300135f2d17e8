// The default thread count leaves the cores other jobs use: by hand from the load average.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/idle_cores.hpp"

using namespace demscale;

TEST_CASE("Idle cores: all minus the load rounded to whole jobs, never fewer than one", "[core][threads]") {
    CHECK(idle_cores(2, 0.0) == 2);
    CHECK(idle_cores(2, 0.4) == 2);   // a trickle of work: both cores
    CHECK(idle_cores(2, 0.6) == 1);   // one job running elsewhere
    CHECK(idle_cores(2, 1.0) == 1);
    CHECK(idle_cores(2, 3.7) == 1);   // overloaded: still one thread
    CHECK(idle_cores(16, 5.2) == 11);
    CHECK(idle_cores(1, 0.0) == 1);
    CHECK(idle_cores(4, std::numeric_limits<double>::quiet_NaN()) == 4);  // no reading: no guess
    CHECK(idle_cores(4, -1.0) == 4);
    if (const auto load = load_average()) CHECK(*load >= 0);  // Linux reports one
}
