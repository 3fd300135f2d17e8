// The slump protocol's engines for wet scenes of unequal spheres: the liquid bridge of each pair's
// harmonic-mean radius: the lines of the engine list (slump/compiled_engines.hpp) with this cohesion
// law, in a file of its own so that it compiles in parallel with the others.
#include "slump/slump_protocol.hpp"

namespace demscale::slump::protocol {

template SlumpResult run_protocol<CohesionLiquidBridgePerPair>(const SlumpScene&, const EngineLine&, Particles, bool,
                                                               const std::function<void(const SlumpProgress&)>&, const SlumpPhases&);

}  // namespace demscale::slump::protocol
