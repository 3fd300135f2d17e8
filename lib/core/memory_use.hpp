// This process's memory as the kernel counts it (Linux /proc/self/status): resident now and the
// peak since the last reset, for the benchmark's bytes per particle. nullopt where not available.
#pragma once

#include <cstddef>
#include <optional>

namespace demscale {

std::optional<std::size_t> resident_bytes();       // VmRSS
std::optional<std::size_t> peak_resident_bytes();  // VmHWM
// Returns freed memory to the system, then sets the peak to what is resident now (writes 5 to /proc/self/clear_refs); false if refused.
bool reset_peak_resident();

}  // namespace demscale
