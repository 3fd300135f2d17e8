// The slump protocol's engine runs, as templates of the contact law: settle, lift, spread, the
// poured fill, checkpoints. run_protocol<Cohesion> compiles the lines of the engine list
// (slump/compiled_engines.hpp) with that cohesion law, each cohesion law in its own file
// (slump_engines_*.cpp), so that the engines build in parallel; slump_run.cpp chooses.
// Included by those files and slump_run.cpp only.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "core/interrupt.hpp"
#include "dem/checkpoint.hpp"
#include "dem/contact_law.hpp"
#include "dem/law_builder.hpp"
#include "dem/law_parts.hpp"
#include "dem/simulation.hpp"
#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "slump/compiled_engines.hpp"
#include "slump/fill.hpp"
#include "slump/motion.hpp"
#include "slump/pour.hpp"
#include "slump/run_cache.hpp"
#include "slump/engine_law.hpp"
#include "slump/slump_run.hpp"

namespace demscale::slump::protocol {

using namespace dem;

// Where the protocol stands: with the engine's own checkpoint, all a resumed run needs.
struct ProtocolState {
    int phase = 0;            // 0 settle, 1 lift, 2 spread
    double still_since = -1;  // s; −1 while some particle moves
    double lift_start = 0, lift_end = 0;
    double wall_s = 0;        // wall time spent before this process
    std::uint8_t settled = 0;
    double settle_end = 0, initial_height = 0, lifted_at = 0;
    FillMeasures fill;
    double pour_time = 0;
    std::uint64_t pour_steps = 0;
    std::uint64_t pile = 0;  // spheres in the pile (a resumed engine is sized by the checkpoint)
};
inline constexpr CheckpointTag slump_checkpoint_tag = "demscale-slump3";  // then the engine's own

// The walls: the floor and the cone, standing (its lift is scheduled later).
inline std::vector<Wall> slump_walls(const SlumpScene& s) {
    FrustumWall cone;
    cone.bottom_radius = 0.5 * s.bottom_diameter_m;
    cone.top_radius = 0.5 * s.top_diameter_m;
    cone.height = s.height_m;
    cone.velocity = Vec3(0, 0, s.lift_speed_m_per_s);
    return {PlaneWall{}, cone};
}

// Steps sim until all but (1 − rest_quantile) of the pile (its `pile` mobile spheres) have been
// slower than the rest speed for rest_duration (true), or until `end` (false). still_since: s, −1
// while moving. before() runs before each step (interrupt checks), after() after it (samples, progress).
template <class Sim, class Before, class After>
bool run_until_rest(Sim& sim, const SlumpScene& s, std::size_t pile, double end, double& still_since, Before before, After after) {
    while (sim.time() < end) {
        before();
        sim.step();
        after();
        if (quantile_slower_than(sim.particles(), pile, s.rest_speed_m_per_s, s.rest_quantile)) {
            if (still_since < 0) still_since = sim.time();
            if (sim.time() - still_since >= s.rest_duration_s) return true;
        } else {
            still_since = -1;
        }
    }
    return false;
}

// The poured fill (slump/pour.hpp), each batch settled by this law's engine with the cone standing.
// An interrupt during the pour stops without a checkpoint (a rerun pours again, identically).
template <class Law>
Particles pour_with(const SlumpScene& s, const Law& law, const std::function<void(const SlumpProgress&)>& progress,
                    const SpatialSort& sort, double& pour_time, std::uint64_t& pour_steps) {
    return pour_fill(s, [&](Particles pile) {
        const std::size_t n = pile.size();
        pile.append(floor_grains(s));
        Simulation<Law, false> sim(std::move(pile), law, slump_walls(s), Vec3(0, 0, -s.gravity), s.dt_s, s.skin_m, sort);
        const auto report_every = static_cast<std::size_t>(std::max(1.0, 0.005 / s.dt_s));
        double still_since = -1;
        auto check = [] {
            if (interrupt_requested()) throw Interrupted("interrupted while pouring the fill (no checkpoint: a rerun pours again)", "");
        };
        run_until_rest(sim, s, n, s.pour_time_s, still_since, check, [&] {
            if (progress && sim.steps() % report_every == 0)
                progress({"pour", pour_time + sim.time(), pour_time + s.pour_time_s, pour_steps + sim.steps(), 0,
                          [&] { return sim.in_input_order(); }});
        });
        pour_time += sim.time(), pour_steps += sim.steps();
        return sim.in_input_order().mobile();
    });
}

// The cone's lift, from the protocol's state: it starts moving at lift_start and stops at lift_end.
template <class Sim>
void schedule_lift(Sim& sim, const ProtocolState& st) {
    auto& cone = std::get<FrustumWall>(sim.walls()[1]);
    cone.move_start = st.lift_start, cone.move_end = st.lift_end;
}

// A resumed run: the protocol's state and history from the checkpoint `path`, the cone as it
// stood, then the engine's own state. Refused (naming --resume) unless an interrupted run of the
// scene with this key wrote it.
template <class Sim>
void resume_checkpoint(Sim& sim, const std::filesystem::path& path, const std::string& key, ProtocolState& st, std::vector<TimePoint>& history) {
    const std::string accepted = "a checkpoint an interrupted run of this scene wrote (scene key " + key + ")";
    std::istringstream in(io::read_input_file("--resume", path.string(), accepted), std::ios::binary);
    try {
        CheckpointReader r(in, slump_checkpoint_tag, "another format");
        std::array<char, 16> stored_key{};
        r.value(stored_key);
        if (std::string(stored_key.data(), 16) != key) throw InputError("--resume", path.string(), accepted);
        r.value(st);
        r.array(history);
    } catch (const InputError&) {
        throw;
    } catch (const std::runtime_error&) {  // another format, or truncated
        throw InputError("--resume", path.string(), accepted);
    }
    if (st.phase >= 1) schedule_lift(sim, st);
    if (st.phase >= 2) sim.remove_wall(1);
    sim.load(in);
}

// Stops the run with Interrupted after its last whole step, first writing the checkpoint `path`
// (atomically) when one is asked for.
template <class Sim>
[[noreturn]] void stop_with_checkpoint(Sim& sim, const std::filesystem::path& path, const std::string& key, const ProtocolState& st,
                                       const std::vector<TimePoint>& history) {
    char where[120];
    std::snprintf(where, sizeof where, "interrupted at t = %.4f s (step %zu)", sim.time(), sim.steps());
    if (path.empty()) throw Interrupted(where, "");
    std::ostringstream out(std::ios::binary);
    CheckpointWriter w(out, slump_checkpoint_tag);
    std::array<char, 16> stored_key{};
    std::copy_n(key.begin(), 16, stored_key.begin());
    w.value(stored_key), w.value(st), w.array(history);
    sim.save(out);
    io::write_file_atomically(path, out.str());
    throw Interrupted(where, path.string());
}

// What every run reports at its end, measured on its final state (in the input's order).
inline void finish(SlumpResult& res, const Particles& end_state, const ProtocolState& st, const SlumpScene& s, std::size_t steps,
                   double wall_s) {
    res.motion = summarize_motion(end_state, res.particles, s.rest_speed_m_per_s);
    res.fill = st.fill, res.pour_time = st.pour_time, res.pour_steps = st.pour_steps;
    res.steps = steps;
    res.final = measure_pile(end_state, s);
    res.final_state = end_state.mobile();
    res.wall_s = wall_s;
}

template <bool Ledger, class Law>
SlumpResult run_with(const SlumpScene& s, Law law, Particles particles, const std::function<void(const SlumpProgress&)>& progress,
                     const SlumpPhases& phases, ProtocolState st = {}) {
    const auto clock_start = std::chrono::steady_clock::now();
    SlumpResult res;
    res.particles = particles.size();
    st.pile = res.particles;
    particles.append(floor_grains(s));  // after the pile: pile indices are the same as without them
    Simulation<Law, Ledger> sim(std::move(particles), std::move(law), slump_walls(s), Vec3(0, 0, -s.gravity), s.dt_s, s.skin_m,
                                phases.spatial_sort);
    const std::string key = scene_key(s);
    if (!phases.resume.empty()) {
        resume_checkpoint(sim, phases.resume, key, st, res.history);
        res.particles = st.pile;
    }
    auto wall_time = [&] { return st.wall_s + std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count(); };
    const auto report_every = static_cast<std::size_t>(std::max(1.0, 0.005 / s.dt_s));
    auto sample = [&] {
        const auto& p = sim.particles();
        double top = 0, spread = 0;
        for (std::size_t i = 0; i < p.size(); ++i)  // the pile, not the floor's grains (maxima: in any order)
            if (!p.fixed[i])
                top = std::max(top, p.position[i].z() + p.radius[i]), spread = std::max(spread, std::hypot(p.position[i].x(), p.position[i].y()));
        res.history.push_back({sim.time(), top, 2 * (spread + s.radius_m), sim.energy()});
    };
    if (phases.resume.empty()) sample();
    auto tick = [&](const std::string& phase, double end) {
        if (sim.steps() % report_every != 0) return;
        sample();
        if (progress) {
            const double wall = wall_time();
            progress({phase, sim.time(), end, sim.steps(), wall > 0 ? double(res.particles * sim.steps()) / wall : 0,
                      [&] { return sim.in_input_order(); }});
        }
    };
    // Called between steps when SIGINT/SIGTERM arrived: the state after the last whole step.
    auto stop_here = [&] {
        st.wall_s = wall_time();
        stop_with_checkpoint(sim, phases.checkpoint, key, st, res.history);
    };
    auto rest = [&](const std::string& phase, double end) {
        return run_until_rest(
            sim, s, res.particles, end, st.still_since, [&] { if (interrupt_requested()) stop_here(); }, [&] { tick(phase, end); });
    };
    if (st.phase == 0) {  // settle (skipped when starting from a settled state), then start the lift
        if (!phases.start) st.settled = rest("settle", s.settle_time_s);
        st.settle_end = sim.time();
        const Particles settled = sim.in_input_order();  // what is reported is measured in the input's order
        if (phases.fill_measures) st.fill = measure_fill(settled, s);
        st.initial_height = measure_pile(settled, s).height;
        if (phases.settle_only) {
            res.settled = st.settled, res.settle_end = st.settle_end, res.initial_height = st.initial_height;
            finish(res, settled, st, s, sim.steps(), wall_time());
            return res;
        }
        st.phase = 1, st.still_since = -1;
        st.lift_start = sim.time();
        st.lift_end = sim.time() + s.lift_height_m / s.lift_speed_m_per_s;
        schedule_lift(sim, st);
    }
    if (st.phase == 1) {
        while (sim.time() < st.lift_end) {
            if (interrupt_requested()) stop_here();
            sim.step();
            tick("lift", st.lift_end);
        }
        st.lifted_at = sim.time();
        sim.remove_wall(1);  // lifted clear, then removed: anything clinging to it falls back
        st.phase = 2, st.still_since = -1;
    }
    res.came_to_rest = rest("spread", st.lifted_at + s.spread_time_s);
    res.settled = st.settled, res.settle_end = st.settle_end, res.initial_height = st.initial_height, res.lift_end = st.lifted_at;
    res.rest_since = res.came_to_rest ? st.still_since : -1;
    res.end = sim.time();
    res.windows_all_threads = sim.governor().windows(true), res.windows_one_thread = sim.governor().windows(false);
    res.memory = sim.memory();
    finish(res, sim.in_input_order(), st, s, sim.steps(), wall_time());
    return res;
}

// The engine of one line of the list (slump/compiled_engines.hpp): its contact law (built by
// dem/law_builder.hpp), the pour (without the ledger) when asked, then the protocol.
template <EngineLine Line, class Cohesion>
SlumpResult run_line(const SlumpScene& s, Particles particles, bool pour, const std::function<void(const SlumpProgress&)>& progress,
                     const SlumpPhases& phases) {
    static_assert(!std::is_void_v<typename law_of<Line.normal, normal_laws>::type>, "an engine line names a normal law registered in dem::normal_laws");
    using Law = EngineLaw<Line>;
    Law law = build_contact_law<Law>(s, law_sizes(s, particles), s.source);
    ProtocolState st;
    if (pour) {  // its wall time counts in the run's
        const auto t0 = std::chrono::steady_clock::now();
        particles = pour_with(s, law, progress, phases.spatial_sort, st.pour_time, st.pour_steps);
        st.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return run_with<Line.ledger>(s, std::move(law), std::move(particles), progress, phases, st);
}

// The whole protocol with this cohesion law, on the engine of `line` (a line of the list with this
// cohesion law: listed_engine chose it), the law built from the scene; pour: fill the cone by pouring first (else `particles` is
// the start). Every line of the list with this cohesion law is compiled here, and only those.
template <class Cohesion>
SlumpResult run_protocol(const SlumpScene& s, const EngineLine& line, Particles particles, bool pour,
                         const std::function<void(const SlumpProgress&)>& progress, const SlumpPhases& phases) {
    SlumpResult result;
    bool ran = false;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        auto try_line = [&]<EngineLine Line>() {
            if constexpr (std::is_same_v<CohesionLaw<Line.cohesion>, Cohesion>)
                if (!ran && Line == line) result = run_line<Line, Cohesion>(s, std::move(particles), pour, progress, phases), ran = true;
        };
        (try_line.template operator()<compiled_engines[I]>(), ...);
    }(std::make_index_sequence<std::size(compiled_engines)>{});
    if (!ran) throw std::logic_error("run_protocol: " + engine_name(line) + " is not a compiled engine of this cohesion law");
    return result;
}

// Built in slump_engines_*.cpp, one file each.
extern template SlumpResult run_protocol<CohesionNone>(const SlumpScene&, const EngineLine&, Particles, bool,
                                                       const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);
extern template SlumpResult run_protocol<CohesionLiquidBridge>(const SlumpScene&, const EngineLine&, Particles, bool,
                                                               const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);
extern template SlumpResult run_protocol<CohesionLiquidBridgePerPair>(const SlumpScene&, const EngineLine&, Particles, bool,
                                                                      const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);
extern template SlumpResult run_protocol<CohesionSjkr>(const SlumpScene&, const EngineLine&, Particles, bool,
                                                       const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);

}  // namespace demscale::slump::protocol
