// The slump protocol: fill the cone, let the fill settle (cone fixed) until at rest or a time limit,
// lift the cone at constant speed and remove it, let the pile spread until at rest or a time limit,
// measure.
// The contact law is chosen once from the scene (dry or wet, with or without rolling resistance);
// each choice is its own compiled engine, so a dry run executes no bridge code.
#pragma once

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/memory_use.hpp"
#include "dem/energy.hpp"
#include "dem/particles.hpp"
#include "dem/spatial_order.hpp"
#include "slump/fill_measures.hpp"
#include "slump/measurements.hpp"
#include "slump/motion.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

struct SlumpProgress {
    std::string phase;        // settle, lift, spread
    double time = 0;          // simulated, s
    double phase_end = 0;     // latest end of the phase, s
    std::size_t steps = 0;
    double particle_steps_per_s = 0;
    std::function<dem::Particles()> state;  // the current state in the input's order (a copy), for snapshots
};

struct TimePoint {
    double time = 0, height = 0, spread_max = 0;  // s, m, m
    dem::Energy energy;                          // the engine's ledger at that time, J
};

struct SlumpResult {
    std::size_t particles = 0, steps = 0;
    double dt = 0, critical_dt = 0, wall_s = 0;
    double settle_end = 0, lift_end = 0, end = 0;  // s
    bool settled = false, came_to_rest = false;
    bool energy_ledger = false;  // the history's losses and wall work were booked
    double initial_height = 0;
    FillMeasures fill;                  // the settled fill, before the lift
    double pour_time = 0;               // simulated time spent pouring (poured fills), s
    std::size_t pour_steps = 0;
    double rest_since = -1;             // s: when the final rest window began; −1: not at rest
    std::vector<MemoryItem> memory;     // the engine's at the run's end, by consumer (bench --dem --sizes)
    MotionSummary motion;               // what still moved at the end
    // The thread governor's windows (dem/thread_governor.hpp) of the lift and spread: on all the
    // run's threads and on one; both 0 when it had one thread. Not cached (speed, not physics).
    std::size_t windows_all_threads = 0, windows_one_thread = 0;
    PileMeasures final;
    std::vector<TimePoint> history;  // at the start, then every 5 ms
    dem::Particles final_state;
    double slump() const { return initial_height - final.height; }
    // The run's work, pour included (counted with the pile's final count: a pour holds a few % more).
    double particle_steps() const { return double(particles) * double(steps + pour_steps); }
    // From the cone's removal to the start of the final rest window, s; NaN when not at rest.
    double time_to_rest() const { return came_to_rest ? rest_since - lift_end : std::nan(""); }
    // Change of the ledger's balance over the run relative to the energy dissipated (0 for an exact
    // integrator; about 1 % at the usual dt). 0 without the ledger.
    double energy_balance_error() const;
};

// Which part of the protocol to run: all of it; only fill and settle (final_state = the settled
// fill, e.g. to hand to another engine); or lift and spread from a given settled state.
// checkpoint: where to write the state when SIGINT/SIGTERM stops the run (none: stop without one);
// resume: a checkpoint to continue from, bit for bit as if never interrupted.
// energy_ledger: book every loss and the walls' work, so that the history carries a balanced ledger
// (about 10 % slower); without it the history has kinetic, gravitational and stored energy only.
struct SlumpPhases {
    bool settle_only = false;
    bool energy_ledger = false;
    bool fill_measures = true;  // false: no fill measures (about 140 sample points per sphere); the size sweep's runs
    const dem::Particles* start = nullptr;  // settled state: skip fill and settle
    std::filesystem::path checkpoint, resume;
    // Where another engine's files go (a LIGGGHTS run's deck, log and dump: slump/liggghts_run.hpp);
    // empty: a temporary folder, removed after the run.
    std::filesystem::path work_dir;
    // When the engines reorder their spheres. Reordering changes a run's last bits, so the commands
    // keep this default, which the run cache's format stands for (scene_text.hpp); tests and
    // benchmarks change it.
    dem::SpatialSort spatial_sort;
};

// The sizes a run's contact law is built for: the scene's reference radius, and the largest of its
// distribution's spheres and of `start`'s (another engine's fill may hold larger ones), m.
dem::LawSizes law_sizes(const SlumpScene& s, const dem::Particles& start);

// Throws InputError naming the scene's run.dt_s when dt exceeds a limit of the laws that act
// (0.2 × the Rayleigh time; 0.2 × the lubrication time of a viscous bridge), unless force_dt.
void check_slump_time_step(const SlumpScene& scene, bool force_dt);
// The time scale of the limit that binds (for the report: the Rayleigh time in the shipped scenes).
double binding_time_scale(const SlumpScene& scene);

// progress is called about every 5 ms of simulated time. Throws InputError for a time step above
// 0.2 × the Rayleigh time (unless force_dt) or a checkpoint of another scene, std::runtime_error if
// the engine stops, and Interrupted (core/interrupt.hpp) after writing the checkpoint on a signal.
// A scene with liggghts_ranks > 0 is lifted and spread by LIGGGHTS (slump/liggghts_run.hpp).
SlumpResult run_slump(const SlumpScene& scene, const std::function<void(const SlumpProgress&)>& progress = {},
                      bool force_dt = false, SlumpPhases phases = {});

}  // namespace demscale::slump
