#include "slump/slump_run.hpp"

#include "dem/checkpoint.hpp"
#include "dem/law_parts.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "bridge/liquid_volume.hpp"
#include "core/interrupt.hpp"
#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "dem/simulation.hpp"
#include "dem/time_step.hpp"
#include "slump/fill.hpp"
#include "slump/motion.hpp"
#include "slump/pour.hpp"
#include "slump/run_cache.hpp"

namespace demscale::slump {

namespace {

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
constexpr CheckpointTag slump_checkpoint_tag = "demscale-slump3";  // then the engine's own

// The walls: the floor and the cone, standing (its lift is scheduled later).
std::vector<Wall> slump_walls(const SlumpScene& s) {
    FrustumWall cone;
    cone.bottom_radius = 0.5 * s.bottom_diameter_m;
    cone.top_radius = 0.5 * s.top_diameter_m;
    cone.height = s.height_m;
    cone.velocity = Vec3(0, 0, s.lift_speed_m_per_s);
    return {PlaneWall{}, cone};
}

// Steps sim until all but (1 − rest_quantile) of the first `pile` spheres have been slower than the
// rest speed for rest_duration (true), or until `end` (false). still_since: s, −1 while moving.
// before() runs before each step (interrupt checks), after() after it (samples, progress).
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
                    double& pour_time, std::uint64_t& pour_steps) {
    return pour_fill(s, [&](Particles pile) {
        const std::size_t n = pile.size();
        pile.append(floor_grains(s));
        Simulation<Law, false> sim(std::move(pile), law, slump_walls(s), Vec3(0, 0, -s.gravity), s.dt_s, s.skin_m);
        const auto report_every = static_cast<std::size_t>(std::max(1.0, 0.005 / s.dt_s));
        double still_since = -1;
        auto check = [] {
            if (interrupt_requested()) throw Interrupted("interrupted while pouring the fill (no checkpoint: a rerun pours again)", "");
        };
        run_until_rest(sim, s, n, s.pour_time_s, still_since, check, [&] {
            if (progress && sim.steps() % report_every == 0)
                progress({"pour", pour_time + sim.time(), pour_time + s.pour_time_s, pour_steps + sim.steps(), 0, &sim.particles()});
        });
        pour_time += sim.time(), pour_steps += sim.steps();
        return sim.particles().mobile();
    });
}

template <bool Ledger, class Law>
SlumpResult run_with(const SlumpScene& s, Law law, Particles particles, const std::function<void(const SlumpProgress&)>& progress,
                     const SlumpPhases& phases, ProtocolState st = {}) {
    const auto clock_start = std::chrono::steady_clock::now();
    SlumpResult res;
    res.particles = particles.size();
    st.pile = res.particles;
    particles.append(floor_grains(s));  // after the pile: pile indices are the same as without them
    Simulation<Law, Ledger> sim(std::move(particles), std::move(law), slump_walls(s), Vec3(0, 0, -s.gravity), s.dt_s, s.skin_m);
    const std::string key = scene_key(s);
    auto schedule_lift = [&] { std::get<FrustumWall>(sim.walls()[1]).move_start = st.lift_start, std::get<FrustumWall>(sim.walls()[1]).move_end = st.lift_end; };
    if (!phases.resume.empty()) {
        const std::string accepted = "a checkpoint an interrupted run of this scene wrote (scene key " + key + ")";
        std::istringstream in(io::read_input_file("--resume", phases.resume.string(), accepted), std::ios::binary);
        try {
            CheckpointReader r(in, slump_checkpoint_tag, "another format");
            std::array<char, 16> stored_key{};
            r.value(stored_key);
            if (std::string(stored_key.data(), 16) != key) throw InputError("--resume", phases.resume.string(), accepted);
            r.value(st);
            r.array(res.history);
        } catch (const InputError&) {
            throw;
        } catch (const std::runtime_error&) {  // another format, or truncated
            throw InputError("--resume", phases.resume.string(), accepted);
        }
        if (st.phase >= 1) schedule_lift();
        if (st.phase >= 2) sim.remove_wall(1);
        sim.load(in);
        res.particles = st.pile;
    }
    auto wall_time = [&] { return st.wall_s + std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count(); };
    const auto report_every = static_cast<std::size_t>(std::max(1.0, 0.005 / s.dt_s));
    auto sample = [&] {
        const auto& p = sim.particles();
        double top = 0, spread = 0;
        for (std::size_t i = 0; i < res.particles; ++i)  // the pile, not the floor's grains
            top = std::max(top, p.position[i].z() + p.radius[i]), spread = std::max(spread, std::hypot(p.position[i].x(), p.position[i].y()));
        res.history.push_back({sim.time(), top, 2 * (spread + s.radius_m), sim.energy()});
    };
    if (phases.resume.empty()) sample();
    auto tick = [&](const std::string& phase, double end) {
        if (sim.steps() % report_every != 0) return;
        sample();
        const auto& p = sim.particles();
        if (progress) {
            const double wall = wall_time();
            progress({phase, sim.time(), end, sim.steps(), wall > 0 ? double(res.particles * sim.steps()) / wall : 0, &p});
        }
    };
    // Called between steps when SIGINT/SIGTERM arrived: the state after the last whole step.
    auto stop_here = [&] {
        char where[120];
        std::snprintf(where, sizeof where, "interrupted at t = %.4f s (step %zu)", sim.time(), sim.steps());
        if (phases.checkpoint.empty()) throw Interrupted(where, "");
        st.wall_s = wall_time();
        std::ostringstream out(std::ios::binary);
        CheckpointWriter w(out, slump_checkpoint_tag);
        std::array<char, 16> stored_key{};
        std::copy_n(key.begin(), 16, stored_key.begin());
        w.value(stored_key), w.value(st), w.array(res.history);
        sim.save(out);
        io::write_file_atomically(phases.checkpoint, out.str());
        throw Interrupted(where, phases.checkpoint.string());
    };
    auto rest = [&](const std::string& phase, double end) {
        return run_until_rest(
            sim, s, res.particles, end, st.still_since, [&] { if (interrupt_requested()) stop_here(); }, [&] { tick(phase, end); });
    };
    if (st.phase == 0) {  // settle (skipped when starting from a settled state), then start the lift
        if (!phases.start) st.settled = rest("settle", s.settle_time_s);
        st.settle_end = sim.time();
        st.fill = measure_fill(sim.particles(), s);
        st.initial_height = measure_pile(sim.particles(), lone_sphere_top(s)).height;
        if (phases.settle_only) {
            res.fill = st.fill, res.pour_time = st.pour_time, res.pour_steps = st.pour_steps;
            res.motion = summarize_motion(sim.particles(), res.particles, s.rest_speed_m_per_s);
            res.settled = st.settled, res.settle_end = st.settle_end, res.initial_height = st.initial_height;
            res.steps = sim.steps();
            res.final = measure_pile(sim.particles(), lone_sphere_top(s));
            res.final_state = sim.particles().mobile();
            res.wall_s = wall_time();
            return res;
        }
        st.phase = 1, st.still_since = -1;
        st.lift_start = sim.time();
        st.lift_end = sim.time() + s.lift_height_m / s.lift_speed_m_per_s;
        schedule_lift();
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
    res.motion = summarize_motion(sim.particles(), res.particles, s.rest_speed_m_per_s);
    res.fill = st.fill, res.pour_time = st.pour_time, res.pour_steps = st.pour_steps;
    res.end = sim.time();
    res.steps = sim.steps();
    res.final = measure_pile(sim.particles(), lone_sphere_top(s));
    res.final_state = sim.particles().mobile();
    res.wall_s = wall_time();
    return res;
}

// The wet law's bridge: liquid per bridge from Eq. 5 with the particle mass, the same V̂ for every
// pair; largest_radius sets the range (the scene's R for its own fills).
template <class Bridge>
Bridge bridge_for(const SlumpScene& s, double largest_radius) {
    const double vhat = bridge_vhat(s);
    Bridge c{bridge::mikami_coefficients(vhat, s.liquid.contact_angle, s.bridge), largest_radius,
             s.liquid.surface_tension_n_per_m, std::nullopt, s.viscosity_pa_s, s.min_gap_ratio * s.radius_m};
    if (s.wet_walls)
        c.wall = bridge::mikami_coefficients(vhat, s.liquid.contact_angle, s.bridge, bridge::BridgeGeometry::sphere_wall);
    return c;
}

}  // namespace

void check_slump_time_step(const SlumpScene& s, bool force_dt) {
    for (const auto& limit : time_step_limits(s, s.radius_m))
        check_time_step(s.dt_s, limit.seconds, limit.fraction, force_dt, s.dt_field, std::string(limit.name));
}

double binding_time_scale(const SlumpScene& s) {
    const auto limits = time_step_limits(s, s.radius_m);
    const auto binding = std::min_element(limits.begin(), limits.end(), [](const TimeScale& a, const TimeScale& b) {
        return a.fraction * a.seconds < b.fraction * b.seconds;
    });
    return binding->seconds;
}

double SlumpResult::energy_balance_error() const {
    if (!energy_ledger || history.size() < 2) return 0;
    const double lost = history.back().energy.dissipated.total() - history.front().energy.dissipated.total();
    return lost > 0 ? (history.back().energy.balance() - history.front().energy.balance()) / lost : 0;
}

SlumpResult run_slump(const SlumpScene& s, const std::function<void(const SlumpProgress&)>& progress, bool force_dt,
                      SlumpPhases phases) {
    check_slump_time_step(s, force_dt);
    const double critical = binding_time_scale(s);
    // A resumed run takes its particles from the checkpoint; the lattice fill only sizes the engine.
    const bool pour = s.fill == FillKind::poured && !phases.start && phases.resume.empty();
    Particles particles = phases.start ? *phases.start : pour ? Particles{} : fill_cone(s);
    SlumpResult res;
    // One explicit switch over the combinations a slump scene can ask for, each with or without the ledger.
    auto run = [&](auto law) {
        ProtocolState st;
        if (pour) {  // its wall time counts in the run's
            const auto t0 = std::chrono::steady_clock::now();
            particles = pour_with(s, law, progress, st.pour_time, st.pour_steps);
            st.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
        return phases.energy_ledger ? run_with<true>(s, std::move(law), std::move(particles), progress, phases, st)
                                    : run_with<false>(s, std::move(law), std::move(particles), progress, phases, st);
    };
    auto with_rolling = [&]<class Cohesion>(Cohesion cohesion) {
        if (!s.rolling_resistance) return run(ContactLaw<NormalHertz, TangentialMindlin, Cohesion>(s.material, cohesion));
        if (s.rolling_model == RollingModel::constant_torque)
            return run(ContactLaw<NormalHertz, TangentialMindlin, Cohesion, RollingConstantTorque>(s.material, cohesion));
        if (s.rolling_model == RollingModel::epsd2)
            return run(ContactLaw<NormalHertz, TangentialMindlin, Cohesion, RollingEpsd2>(s.material, cohesion));
        return run(ContactLaw<NormalHertz, TangentialMindlin, Cohesion, RollingEpsd>(s.material, cohesion));
    };
    // The protocol's own fills are monodisperse. A wet start state with unequal radii (another
    // engine's fill) is refused rather than bridged with one R: the per-pair bridge
    // (CohesionMikamiBridgePerPair) would double the compiled wet engines, for no shipped scene.
    const auto [smallest, largest] = std::minmax_element(particles.radius.begin(), particles.radius.end());
    if (s.wet && smallest != particles.radius.end() && *smallest != *largest)
        throw InputError("--start", "radii from " + format_short(*smallest * 1e3) + " to " + format_short(*largest * 1e3) + " mm",
                         "spheres of one radius for a wet scene (equal-sphere bridges; docs/models/liquid-bridge.md)");
    res = s.wet                  ? with_rolling(bridge_for<CohesionMikamiBridge>(s, s.radius_m))
          : sjkr_part.active(s) ? with_rolling(CohesionSjkr{s.cohesion_energy_density})
                                : with_rolling(CohesionNone{});
    res.energy_ledger = phases.energy_ledger;
    res.dt = s.dt_s;
    res.critical_dt = critical;
    return res;
}

}  // namespace demscale::slump
