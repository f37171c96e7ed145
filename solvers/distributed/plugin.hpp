// The PETSc/SLEPc plugin (distributed/plugin_abi.h), loaded on first use or at start-up under
// mpirun: for the solves that call it; the ranks and their collectives are distributed.hpp's.
#pragma once
#include <string>

#include "distributed/plugin_abi.h"

namespace bb::distributed {

// The plugin, started; InputError naming `what_needs_it` and how to get it when this build has no
// plugin, SolverError when it cannot be loaded or MPI and PETSc cannot start.
const bb_plugin& plugin(const std::string& what_needs_it);

}  // namespace bb::distributed
