#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace demscale {

namespace {
std::atomic<int> requested{-1};  // -1: no; 0: requested directly; else the signal number
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int sig) {
    requested.store(sig, std::memory_order_relaxed);
    std::signal(sig, SIG_DFL);  // a second Ctrl-C ends the process at once
}
}  // namespace

void install_interrupt_handlers() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}
bool interrupt_requested() { return requested.load(std::memory_order_relaxed) >= 0; }
void request_interrupt() { requested.store(0, std::memory_order_relaxed); }
void clear_interrupt() { requested.store(-1, std::memory_order_relaxed); }
int interrupt_signal() { return std::max(requested.load(std::memory_order_relaxed), 0); }

}  // namespace demscale
