// Choosing, window by window, between all the threads a run was given and one. On a machine where
// another job holds a core, threads that wait for each other at every step's barriers can run many
// times slower than one thread (docs/performance.md: 23 s quiet, 182 s with one core busy). The
// governor times windows of steps (at least 0.2 s and 20 steps) in the mode it chose, and now and
// then, or at once when a window runs 1.5 times slower than the last, times one window in the
// other mode (a shorter one, 0.05 s, on one thread), then one more in its own, and keeps one
// thread only when it was 15 % faster than all threads (probe against the mean of the windows
// around it: a cost that drifts over a run cancels). It starts on all threads and probes after
// its first window.
// How often: having chosen one thread it probes again after 2 windows, then 4, 8, … up to
// `probe_every` while one thread keeps winning (on a shared machine a window's noise can pass for
// contention, and a wrong choice then costs a few windows); on all threads after 12 windows, then
// 24, 48, … up to `longest_hold` while all threads keep winning (each probe runs a window on one
// thread: 7 of 89 windows of a quiet 2-core run did, docs/performance.md).
// Trajectories do not depend on the thread count, nor do the energy ledger's sums (per share of the
// work, simulation.hpp), so the choice changes only the speed.
#pragma once

#include <chrono>
#include <cstddef>

namespace demscale::dem {

class ThreadGovernor {
public:
    static constexpr int probe_every = 24;   // windows between probes, on one thread at most
    static constexpr int longest_hold = 96;  // on all threads at most
    static constexpr double one_thread_margin = 0.85;  // one thread's time over all threads' to choose it
    // A window lasts at least 20 steps and this long, s; a probe's window on one thread a quarter
    // of it: on a quiet machine each probe runs on one thread, and the modes' times differ by far
    // more than the margin (1.7x quiet, 2-8x contended, docs/performance.md).
    static constexpr double window_s = 0.2, probe_window_s = 0.05;

    // threads: what the run was given; 1 turns the governor off.
    explicit ThreadGovernor(int threads) : most_(threads), current_(threads) {}

    int threads() const { return current_; }  // for the next step
    bool active() const { return most_ > 1; }

    // After each step, with the time now.
    void stepped(std::chrono::steady_clock::time_point now);

    // Windows run in each mode.
    std::size_t windows(bool all_threads) const { return windows_[all_threads]; }

private:
    enum class Stage { settled, probe, confirm };
    int most_, current_;
    Stage stage_ = Stage::settled;
    bool started_ = false;
    std::chrono::steady_clock::time_point window_start_;
    std::size_t window_steps_ = 0;
    std::size_t windows_[2] = {0, 0};  // [0] one thread, [1] all
    int hold_ = probe_every / 2;         // windows between probes now
    int settled_windows_ = hold_ - 1;  // since the last probe: the first window probes
    double last_settled_ = 0, before_ = 0, probe_ = 0;  // s per step
};

}  // namespace demscale::dem
