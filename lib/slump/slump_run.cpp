#include "slump/slump_run.hpp"

#include <chrono>

#include "bridge/liquid_volume.hpp"
#include "dem/simulation.hpp"
#include "dem/time_step.hpp"
#include "slump/fill.hpp"

namespace demscale::slump {

namespace {

using namespace dem;

double max_speed(const Particles& p) {
    double v = 0;
    for (const auto& x : p.velocity) v = std::max(v, x.norm());
    return v;
}

template <class Law>
SlumpResult run_with(const SlumpScene& s, Law law, Particles particles, const std::function<void(const SlumpProgress&)>& progress,
                     SlumpPhases phases) {
    const auto clock_start = std::chrono::steady_clock::now();
    FrustumWall cone;
    cone.bottom_radius = 0.5 * s.bottom_diameter_m;
    cone.top_radius = 0.5 * s.top_diameter_m;
    cone.height = s.height_m;
    cone.velocity = Vec3(0, 0, s.lift_speed_m_per_s);
    SlumpResult res;
    res.particles = particles.size();
    Simulation<Law> sim(std::move(particles), std::move(law), {PlaneWall{}, cone}, Vec3(0, 0, -s.gravity), s.dt_s, s.skin_m);
    const auto report_every = static_cast<std::size_t>(std::max(1.0, 0.005 / s.dt_s));
    auto tick = [&](const std::string& phase, double end) {
        if (sim.steps() % report_every != 0) return;
        const auto& p = sim.particles();
        double top = 0, spread = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
            top = std::max(top, p.position[i].z() + p.radius[i]), spread = std::max(spread, std::hypot(p.position[i].x(), p.position[i].y()));
        res.history.push_back({sim.time(), top, 2 * (spread + s.radius_m), sim.energy().kinetic});
        if (progress) {
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
            progress({phase, sim.time(), end, sim.steps(), wall > 0 ? double(res.particles * sim.steps()) / wall : 0, &p});
        }
    };
    // Runs until every particle has been slower than rest_speed for rest_duration, or until `end`.
    auto run_until_rest = [&](const std::string& phase, double end) {
        double still_since = -1;
        while (sim.time() < end) {
            sim.step();
            tick(phase, end);
            if (max_speed(sim.particles()) < s.rest_speed_m_per_s) {
                if (still_since < 0) still_since = sim.time();
                if (sim.time() - still_since >= s.rest_duration_s) return true;
            } else {
                still_since = -1;
            }
        }
        return false;
    };

    if (!phases.start) res.settled = run_until_rest("settle", s.settle_time_s);
    res.settle_end = sim.time();
    res.initial_height = measure_pile(sim.particles()).height;
    if (phases.settle_only) {
        res.steps = sim.steps();
        res.final = measure_pile(sim.particles());
        res.final_state = sim.particles();
        res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
        return res;
    }
    auto& lifted = std::get<FrustumWall>(sim.walls()[1]);
    lifted.move_start = sim.time();
    lifted.move_end = sim.time() + s.lift_height_m / s.lift_speed_m_per_s;
    while (sim.time() < lifted.move_end) {
        sim.step();
        tick("lift", lifted.move_end);
    }
    res.lift_end = sim.time();
    sim.remove_wall(1);  // lifted clear, then removed: anything clinging to it falls back
    res.came_to_rest = run_until_rest("spread", res.lift_end + s.spread_time_s);
    res.end = sim.time();
    res.steps = sim.steps();
    res.final = measure_pile(sim.particles());
    res.final_state = sim.particles();
    res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    return res;
}

// The wet law's bridge: liquid per bridge from Eq. 5 with the particle mass.
CohesionMikamiBridge bridge_for(const SlumpScene& s) {
    const double mass = s.material.density * 4.0 / 3.0 * M_PI * std::pow(s.radius_m, 3);
    const double volume = bridge::liquid_bridge_volume(s.liquid.moisture_content, mass, s.liquid.density_kg_per_m3);
    const double vhat = volume / std::pow(s.radius_m, 3);
    CohesionMikamiBridge c{bridge::mikami_coefficients(vhat, s.liquid.contact_angle, s.bridge), s.radius_m,
                           s.liquid.surface_tension_n_per_m, std::nullopt};
    if (s.wet_walls)
        c.wall = bridge::mikami_coefficients(vhat, s.liquid.contact_angle, s.bridge, bridge::BridgeGeometry::sphere_wall);
    return c;
}

}  // namespace

SlumpResult run_slump(const SlumpScene& s, const std::function<void(const SlumpProgress&)>& progress, bool force_dt,
                      SlumpPhases phases) {
    const double critical = rayleigh_time(s.material, s.radius_m);
    check_time_step(s.dt_s, critical, 0.2, force_dt);
    Particles particles = phases.start ? *phases.start : fill_cone(s);
    SlumpResult res;
    // One explicit switch over the combinations a slump scene can ask for.
    if (s.wet && s.rolling_resistance)
        res = run_with(s, ContactLaw<NormalHertz, TangentialMindlin, CohesionMikamiBridge, RollingEpsd>(s.material, bridge_for(s)),
                       std::move(particles), progress, phases);
    else if (s.wet)
        res = run_with(s, ContactLaw<NormalHertz, TangentialMindlin, CohesionMikamiBridge>(s.material, bridge_for(s)),
                       std::move(particles), progress, phases);
    else if (s.rolling_resistance)
        res = run_with(s, ContactLaw<NormalHertz, TangentialMindlin, CohesionNone, RollingEpsd>(s.material), std::move(particles),
                       progress, phases);
    else
        res = run_with(s, ContactLaw<NormalHertz, TangentialMindlin>(s.material), std::move(particles), progress, phases);
    res.dt = s.dt_s;
    res.critical_dt = critical;
    return res;
}

}  // namespace demscale::slump
