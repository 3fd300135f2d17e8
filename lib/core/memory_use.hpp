// This process's memory as the kernel counts it (Linux /proc/self/status): resident now and the
// peak since the last reset, for the benchmark's bytes per particle. nullopt where not available.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace demscale {

std::optional<std::size_t> resident_bytes();       // VmRSS
std::optional<std::size_t> peak_resident_bytes();  // VmHWM
// Returns freed memory to the system, then sets the peak to what is resident now (writes 5 to /proc/self/clear_refs); false if refused.
bool reset_peak_resident();

// One named consumer of an engine's memory: what its containers hold (their capacities), bytes.
struct MemoryItem {
    std::string name;
    std::size_t bytes;
};
template <class T>
std::size_t capacity_bytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}
template <class T>
std::size_t capacity_bytes(const std::vector<std::vector<T>>& v) {
    std::size_t n = v.capacity() * sizeof(std::vector<T>);
    for (const auto& inner : v) n += capacity_bytes(inner);
    return n;
}

}  // namespace demscale
