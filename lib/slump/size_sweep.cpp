#include "slump/size_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "core/memory_use.hpp"
#include "dem/neighbor_list.hpp"
#include "slump/fill.hpp"
#include "slump/slump_run.hpp"

namespace demscale::slump {

SlumpScene scaled_cone(const SlumpScene& scene, double f) {
    SlumpScene s = scene;
    s.bottom_diameter_m *= f, s.top_diameter_m *= f, s.height_m *= f;
    s.lift_height_m *= f, s.fill_height_m *= f, s.rough_floor_diameter_m *= f;
    return s;
}

dem::Particles packed_fill(const SlumpScene& scene, bool shuffled) {
    constexpr double shrink = 1 / 1.01;
    const dem::Particles lattice = fill_cone(scene);
    const double floor_z = std::min_element(lattice.position.begin(), lattice.position.end(),
                                            [](const dem::Vec3& a, const dem::Vec3& b) { return a.z() < b.z(); })->z();
    std::vector<std::size_t> order(lattice.size());
    std::iota(order.begin(), order.end(), 0);
    if (shuffled) std::shuffle(order.begin(), order.end(), std::mt19937(scene.seed));
    dem::Particles p;
    for (std::size_t i : order) {
        const auto& x = lattice.position[i];
        const double r = lattice.radius[i], rho = lattice.mass[i] / (4.0 / 3.0 * std::numbers::pi * r * r * r);
        p.add({x.x() * shrink, x.y() * shrink, floor_z + (x.z() - floor_z) * shrink}, r, rho);
    }
    return p;
}

namespace {

// One run of about `steps` steps from `start`: half lifting the cone, half spreading; no stop at rest.
SlumpResult stepped(SlumpScene s, const dem::Particles& start, int steps) {
    s.rest_duration_s = 1e30;
    s.lift_height_m = s.lift_speed_m_per_s * s.dt_s * (steps / 2);
    s.spread_time_s = s.dt_s * (steps - steps / 2);
    SlumpPhases phases;
    phases.start = &start;
    phases.fill_measures = false;
    return run_slump(s, {}, true, phases);
}

}  // namespace

double contacts_per_particle(const dem::Particles& p) {
    if (p.size() == 0) return 0;
    dem::NeighborList touching(1e-9 * *std::min_element(p.radius.begin(), p.radius.end()));  // every overlapping pair listed
    touching.build(p);
    std::size_t contacts = 0;
    for (const auto& [i, j] : touching.pairs())
        if ((p.position[i] - p.position[j]).norm() < p.radius[i] + p.radius[j]) ++contacts;
    return static_cast<double>(contacts) / static_cast<double>(p.size());
}

SizePoint time_size(const SlumpScene& scene, double particles, int steps, bool shuffled, double timed_work) {
    // Two rounds: size from the small fill's count, then correct by the count reached.
    double factor = std::cbrt(particles / static_cast<double>(fill_cone(scene).size()));
    factor *= std::cbrt(particles / static_cast<double>(fill_cone(scaled_cone(scene, factor)).size()));
    const SlumpScene s = scaled_cone(scene, factor);
    const dem::Particles start = packed_fill(s, shuffled);
    const double timed_per_pair = 2.0 * static_cast<double>(steps) * static_cast<double>(start.size());
    const int pairs = std::max(1, static_cast<int>(std::ceil(timed_work / timed_per_pair)));

    stepped(s, start, steps);  // warm-up: threads started, memory touched
    SizePoint point;
    point.particles = start.size();
    const auto before = resident_bytes();
    const bool peak_reset = reset_peak_resident();
    for (int k = 0; k < pairs; ++k) {
        const SlumpResult shorter = stepped(s, start, steps);
        const SlumpResult longer = stepped(s, start, 3 * steps);
        point.steps += longer.steps - shorter.steps;
        point.wall_s += longer.wall_s - shorter.wall_s;
        if (k + 1 == pairs) point.contacts_per_particle = contacts_per_particle(longer.final_state), point.engine_memory = longer.memory;
    }
    const auto peak = peak_resident_bytes();
    if (point.wall_s > 0) {
        point.particle_steps_per_s = static_cast<double>(point.particles) * static_cast<double>(point.steps) / point.wall_s;
        point.contact_steps_per_s = point.particle_steps_per_s * point.contacts_per_particle;
    }
    if (before && peak && peak_reset && *peak > *before)
        point.peak_bytes_per_particle = static_cast<double>(*peak - *before) / static_cast<double>(point.particles);
    return point;
}

}  // namespace demscale::slump
