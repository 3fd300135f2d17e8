// The slump protocol's engines for dry adhesive scenes: SJKR adhesion: the lines of the engine list
// (slump/compiled_engines.hpp) with this cohesion law, one cohesion law per file so that they compile in parallel.
#include "slump/slump_protocol.hpp"

namespace demscale::slump::protocol {

template SlumpResult run_protocol<CohesionSjkr>(const SlumpScene&, const EngineLine&, Particles, bool,
                                         const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);

}  // namespace demscale::slump::protocol

// The engines the tests share (slump/shared_engines.hpp), compiled here once.
template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::sjkr_epsd_ledger>, demscale::slump::shared::sjkr_epsd_ledger.ledger>;
