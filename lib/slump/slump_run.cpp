#include "slump/slump_run.hpp"

#include <algorithm>
#include <functional>

#include "dem/law_parts.hpp"
#include "dem/time_step.hpp"
#include "slump/liggghts_run.hpp"
#include "slump/slump_protocol.hpp"

namespace demscale::slump {

using namespace dem;

void check_slump_time_step(const SlumpScene& s, bool force_dt) {
    for (const auto& limit : time_step_limits(s, smallest_radius(s)))
        check_time_step(s.dt_s, limit.seconds, limit.fraction, force_dt, s.dt_field, std::string(limit.name));
}

double binding_time_scale(const SlumpScene& s) {
    const auto limits = time_step_limits(s, smallest_radius(s));
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

LawSizes law_sizes(const SlumpScene& s, const Particles& start) {
    double largest = largest_radius(s);
    for (const double r : start.radius) largest = std::max(largest, r);
    return {s.radius_m, largest};
}

SlumpResult run_slump(const SlumpScene& s, const std::function<void(const SlumpProgress&)>& progress, bool force_dt,
                      SlumpPhases phases) {
    if (s.liggghts_ranks > 0 && !phases.settle_only) return run_by_liggghts(s, progress, force_dt, phases);
    // A start state of unequal spheres (another engine's fill) takes each pair's bridge radius.
    const bool unequal_start = phases.start && std::adjacent_find(phases.start->radius.begin(), phases.start->radius.end(),
                                                                   std::not_equal_to<>()) != phases.start->radius.end();
    const EngineLine line = listed_engine(s, phases.energy_ledger, unequal_start);  // before any work: exit 2 when not compiled
    check_slump_time_step(s, force_dt);
    const double critical = binding_time_scale(s);
    // A resumed run takes its particles from the checkpoint; the lattice fill only sizes the engine.
    const bool pour = s.fill == FillKind::poured && !phases.start && phases.resume.empty();
    Particles particles = phases.start ? *phases.start : pour ? Particles{} : fill_cone(s);
    SlumpResult res;
    // Each cohesion law's engines are compiled in a file of their own (slump_engines_*.cpp); they
    // take the normal and rolling laws and the ledger from the line and build the law.
    using protocol::run_protocol;
    switch (line.cohesion) {
        case CohesionChoice::liquid_bridge: res = run_protocol<CohesionLiquidBridge>(s, line, std::move(particles), pour, progress, phases); break;
        case CohesionChoice::liquid_bridge_pairs:
            res = run_protocol<CohesionLiquidBridgePerPair>(s, line, std::move(particles), pour, progress, phases);
            break;
        case CohesionChoice::sjkr: res = run_protocol<CohesionSjkr>(s, line, std::move(particles), pour, progress, phases); break;
        case CohesionChoice::none: res = run_protocol<CohesionNone>(s, line, std::move(particles), pour, progress, phases); break;
    }
    res.energy_ledger = phases.energy_ledger;
    res.dt = s.dt_s;
    res.critical_dt = critical;
    return res;
}

}  // namespace demscale::slump
