// The law and engine of a line of the engine list (slump/compiled_engines.hpp), and the lines
// whose engines the tests share with the library (slump/shared_engines.hpp declares them extern;
// slump_engines_*.cpp define them).
#pragma once

#include <algorithm>
#include <type_traits>

#include "dem/contact_law.hpp"
#include "dem/law_parts.hpp"
#include "dem/simulation.hpp"
#include "slump/compiled_engines.hpp"

namespace demscale::slump {

template <CohesionChoice C>
using CohesionLaw = std::conditional_t<
    C == CohesionChoice::liquid_bridge, dem::CohesionLiquidBridge,
    std::conditional_t<C == CohesionChoice::liquid_bridge_pairs, dem::CohesionLiquidBridgePerPair,
                       std::conditional_t<C == CohesionChoice::sjkr, dem::CohesionSjkr, dem::CohesionNone>>>;
template <RollingEngine R>
using RollingLaw = std::conditional_t<R == RollingEngine::none, dem::RollingNone,
                                      std::conditional_t<R == RollingEngine::epsd, dem::RollingEpsd, dem::RollingChosen>>;

// The contact law of a line: its registered normal law, Mindlin, its cohesion and rolling laws.
template <EngineLine Line>
using EngineLaw = dem::ContactLaw<typename dem::law_of<Line.normal, dem::normal_laws>::type, dem::TangentialMindlin,
                                  CohesionLaw<Line.cohesion>, RollingLaw<Line.rolling>>;
template <EngineLine Line>
using Engine = dem::Simulation<EngineLaw<Line>, Line.ledger>;

// The lines whose engines the tests share: Hertz–Mindlin dry with epsd (ledger off and on), bare
// with the ledger, wet with epsd (ledger off and on), SJKR with epsd and the ledger.
namespace shared {
inline constexpr EngineLine dry_epsd{&dem::hertz_part, CohesionChoice::none, RollingEngine::epsd, false};
inline constexpr EngineLine dry_epsd_ledger{&dem::hertz_part, CohesionChoice::none, RollingEngine::epsd, true};
inline constexpr EngineLine bare_ledger{&dem::hertz_part, CohesionChoice::none, RollingEngine::none, true};
inline constexpr EngineLine wet_epsd{&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::epsd, false};
inline constexpr EngineLine wet_epsd_ledger{&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::epsd, true};
inline constexpr EngineLine sjkr_epsd_ledger{&dem::hertz_part, CohesionChoice::sjkr, RollingEngine::epsd, true};
}  // namespace shared

constexpr bool listed(const EngineLine& line) {
    return std::find(std::begin(compiled_engines), std::end(compiled_engines), line) != std::end(compiled_engines);
}
static_assert(listed(shared::dry_epsd) && listed(shared::dry_epsd_ledger) && listed(shared::bare_ledger) && listed(shared::wet_epsd) &&
                  listed(shared::wet_epsd_ledger) && listed(shared::sjkr_epsd_ledger),
              "a shared engine is a line of the engine list");

}  // namespace demscale::slump

