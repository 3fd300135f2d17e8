#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace demscale {

namespace {
std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);  // safe to set from a signal handler

extern "C" void on_signal(int sig) {
    requested.store(true, std::memory_order_relaxed);
    std::signal(sig, SIG_DFL);  // a second Ctrl-C ends the process at once
}
}  // namespace

void install_interrupt_handlers() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}
bool interrupt_requested() { return requested.load(std::memory_order_relaxed); }
void request_interrupt() { requested.store(true, std::memory_order_relaxed); }
void clear_interrupt() { requested.store(false, std::memory_order_relaxed); }

}  // namespace demscale
