// The slump protocol's engines for wet scenes: the Mikami liquid bridge (each rolling law, with and
// without the ledger): one cohesion law per file, so that they compile in parallel.
#include "slump/slump_protocol.hpp"

namespace demscale::slump::protocol {

template SlumpResult run_protocol<CohesionLiquidBridge>(const SlumpScene&, CohesionLiquidBridge, Particles, bool, const std::function<void(const SlumpProgress&)>&,
                                         const SlumpPhases&);

}  // namespace demscale::slump::protocol
