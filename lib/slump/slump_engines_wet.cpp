// The slump protocol's engines for wet scenes: the Mikami liquid bridge: the lines of the engine list
// (slump/compiled_engines.hpp) with this cohesion law, one cohesion law per file so that they compile in parallel.
#include "slump/slump_protocol.hpp"

namespace demscale::slump::protocol {

template SlumpResult run_protocol<CohesionLiquidBridge>(const SlumpScene&, const EngineLine&, Particles, bool,
                                         const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);

}  // namespace demscale::slump::protocol

// The engines the tests share (slump/shared_engines.hpp), compiled here once.
template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::wet_epsd>, demscale::slump::shared::wet_epsd.ledger>;
template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::wet_epsd_ledger>, demscale::slump::shared::wet_epsd_ledger.ledger>;
