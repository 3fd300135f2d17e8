// The slump protocol's engines for dry scenes: no cohesion code in the force loop: the lines of the engine list
// (slump/compiled_engines.hpp) with this cohesion law, one cohesion law per file so that they compile in parallel.
#include "slump/slump_protocol.hpp"

namespace demscale::slump::protocol {

template SlumpResult run_protocol<CohesionNone>(const SlumpScene&, const EngineLine&, Particles, bool,
                                         const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);

}  // namespace demscale::slump::protocol

// The engines the tests share (slump/shared_engines.hpp), compiled here once.
template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::dry_epsd>, demscale::slump::shared::dry_epsd.ledger>;
template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::dry_epsd_ledger>, demscale::slump::shared::dry_epsd_ledger.ledger>;
template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::bare_ledger>, demscale::slump::shared::bare_ledger.ledger>;
