// A shared library of bladebench's own (linalg/mumps_module, the PETSc/SLEPc plugin) opened at run
// time into a symbol scope of its own (RTLD_LOCAL), so that its dependencies never resolve to, or
// stand in for, another module's libraries that define the same symbols.
#pragma once
#include <string>
#include <vector>

namespace bb {

// The first of `candidates` that exists, opened, and its `entry` symbol; SolverError naming `what`
// and every path tried when none exists, or why the one found cannot be opened or lacks `entry`.
void* run_time_module_entry(const std::vector<std::string>& candidates, const char* entry, const std::string& what);

}  // namespace bb
