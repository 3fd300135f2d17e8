#include "dem/thread_governor.hpp"

#include <algorithm>

namespace demscale::dem {

void ThreadGovernor::stepped(std::chrono::steady_clock::time_point now) {
    if (!active()) return;
    if (!started_) {  // the first step's time includes the engine's set-up: not counted
        started_ = true, window_start_ = now, window_steps_ = 0;
        return;
    }
    ++window_steps_;
    const double elapsed = std::chrono::duration<double>(now - window_start_).count();
    // A probe on one thread is short (on a quiet machine every probe is one); a probe of all
    // threads, from one, lasts a full window: a lucky short window under contention would bring
    // back the threads that wait for windows on end.
    const bool short_probe = stage_ == Stage::probe && current_ == 1;
    if (window_steps_ < 20 || elapsed < (short_probe ? probe_window_s : window_s)) return;
    const bool all = current_ == most_;
    const double per_step = elapsed / static_cast<double>(window_steps_);
    ++windows_[all];
    window_start_ = now, window_steps_ = 0;
    const int other = all ? 1 : most_;
    switch (stage_) {
    case Stage::settled:
        // Probe after hold_ windows, or now if this one slowed down by half.
        if (++settled_windows_ >= hold_ || (last_settled_ > 0 && per_step > 1.5 * last_settled_))
            stage_ = Stage::probe, before_ = per_step, current_ = other;
        last_settled_ = per_step;
        return;
    case Stage::probe:  // back to the settled mode for one window: its time on both sides of the probe
        stage_ = Stage::confirm, probe_ = per_step, current_ = other;
        return;
    case Stage::confirm: {
        // The probe against the mean of the windows around it (a cost that drifts over the run
        // cancels); one thread only when 15 % faster, so a window's noise is not taken for
        // contention (all threads at most 1.18x slower than one is within the 1.2x kept).
        const double settled = 0.5 * (before_ + per_step);
        const bool probe_was_all = !all;
        const double one = probe_was_all ? settled : probe_, many = probe_was_all ? probe_ : settled;
        current_ = one < one_thread_margin * many ? 1 : most_;
        // On one thread, look again soon, then ever less often while one thread keeps winning:
        // a noisy window that chose one thread on a quiet machine costs a few windows, not
        // probe_every; lasting contention costs a probe window in ever more. On all threads,
        // ever less often too while they keep winning (up to longest_hold): each probe runs a
        // window on one thread, and contention that starts later shows as a window 1.5x slower.
        if (current_ == most_) hold_ = all ? std::min(2 * hold_, longest_hold) : probe_every;
        else hold_ = all ? 2 : std::min(2 * hold_, probe_every);
        stage_ = Stage::settled, settled_windows_ = 0, last_settled_ = 0;
        return;
    }
    }
}

}  // namespace demscale::dem
