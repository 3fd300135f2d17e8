// How many cores no other job is using, from the 1-minute load average: an OpenMP run that puts a
// spinning thread on a busy core waits at every barrier for a thread the kernel has parked, and
// runs many times slower than on one thread (docs/performance.md). Used for the default thread
// count; an explicit --threads is the user's choice.
#pragma once

#include <optional>

namespace demscale {

// cores minus the load rounded to the nearest job, at least 1 and at most cores.
int idle_cores(int cores, double load_average);

// The 1-minute load average, when the system reports one.
std::optional<double> load_average();

}  // namespace demscale
