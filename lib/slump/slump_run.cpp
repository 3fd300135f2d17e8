#include "slump/slump_run.hpp"

#include <algorithm>

#include "dem/law_parts.hpp"
#include "dem/time_step.hpp"
#include "slump/liggghts_run.hpp"
#include "slump/slump_protocol.hpp"

namespace demscale::slump {

using namespace dem;

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
    if (s.liggghts_ranks > 0 && !phases.settle_only) return run_by_liggghts(s, progress, force_dt, phases);
    const EngineLine line = listed_engine(s, phases.energy_ledger);  // before any work: exit 2 when not compiled
    check_slump_time_step(s, force_dt);
    const double critical = binding_time_scale(s);
    // A resumed run takes its particles from the checkpoint; the lattice fill only sizes the engine.
    const bool pour = s.fill == FillKind::poured && !phases.start && phases.resume.empty();
    Particles particles = phases.start ? *phases.start : pour ? Particles{} : fill_cone(s);
    SlumpResult res;
    // The protocol's own fills are monodisperse. A wet start state with unequal radii (another
    // engine's fill) is refused rather than bridged with one R: the per-pair bridge
    // (CohesionLiquidBridgePerPair) would double the compiled wet engines, for no shipped scene.
    const auto [smallest, largest] = std::minmax_element(particles.radius.begin(), particles.radius.end());
    if (s.wet && smallest != particles.radius.end() && *smallest != *largest)
        throw InputError("--start", "radii from " + format_short(*smallest * 1e3) + " to " + format_short(*largest * 1e3) + " mm",
                         "spheres of one radius for a wet scene (equal-sphere bridges; docs/models/liquid-bridge.md)");
    // Each cohesion law's engines are compiled in a file of their own (slump_engines_*.cpp); they
    // take the normal and rolling laws and the ledger from the line and build the law.
    using protocol::run_protocol;
    res = line.cohesion == CohesionChoice::liquid_bridge ? run_protocol<CohesionLiquidBridge>(s, line, std::move(particles), pour, progress, phases)
          : line.cohesion == CohesionChoice::sjkr        ? run_protocol<CohesionSjkr>(s, line, std::move(particles), pour, progress, phases)
                                                         : run_protocol<CohesionNone>(s, line, std::move(particles), pour, progress, phases);
    res.energy_ledger = phases.energy_ledger;
    res.dt = s.dt_s;
    res.critical_dt = critical;
    return res;
}

}  // namespace demscale::slump
