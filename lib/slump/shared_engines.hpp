// The engines the library compiles that the engine tests build too: declared extern here, defined
// once in slump_engines_*.cpp, so a test that includes this header links the library's copy
// instead of compiling its own (docs/development.md). Tests only: the engines files, which define
// them, do not include it.
#pragma once

#include "slump/engine_law.hpp"

extern template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::dry_epsd>, false>;
extern template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::dry_epsd_ledger>, true>;
extern template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::bare_ledger>, true>;
extern template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::wet_epsd>, false>;
extern template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::wet_epsd_ledger>, true>;
extern template class demscale::dem::Simulation<demscale::slump::EngineLaw<demscale::slump::shared::sjkr_epsd_ledger>, true>;
