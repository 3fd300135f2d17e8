#include "core/memory_use.hpp"

#include <fstream>
#include <malloc.h>
#include <string>

namespace demscale {

namespace {
std::optional<std::size_t> status_kib(const std::string& field) {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.rfind(field + ":", 0) == 0) return std::stoull(line.substr(field.size() + 1)) * 1024;
    return std::nullopt;
}
}  // namespace

std::optional<std::size_t> resident_bytes() { return status_kib("VmRSS"); }
std::optional<std::size_t> peak_resident_bytes() { return status_kib("VmHWM"); }

bool reset_peak_resident() {
    ::malloc_trim(0);  // freed memory the allocator still holds would hide the next run's growth
    std::ofstream out("/proc/self/clear_refs");
    return static_cast<bool>(out << "5" << std::flush);
}

}  // namespace demscale
