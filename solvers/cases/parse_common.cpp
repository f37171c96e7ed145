#include "cases/parse_common.hpp"

#include "distributed/distributed.hpp"

namespace bb {

Direction parse_direction(TomlReader& r, const std::string& key, const std::string& value) {
  if (value == "x") return 0;
  if (value == "y") return 1;
  if (value == "z") return 2;
  r.fail(key, fmt::format("unknown direction '{}'; expected x, y or z", value));
}

LoadSplit parse_split(TomlReader& r, const std::string& key) {
  return r.choice(key, {"equal", "consistent"}) == "equal" ? LoadSplit::equal : LoadSplit::consistent_edge;
}

Eigensolver parse_eigensolver(TomlReader& r) {
  if (r.choice("eigensolver", {"spectra", "slepc"}, "spectra") == "spectra") return Eigensolver::spectra;
  if (!distributed::built_with_slepc())
    r.fail("eigensolver",
           "\"slepc\" needs a bladebench built with PETSc/SLEPc: install Debian's libslepc-real-dev and "
           "libpetsc-real-dev (./run.sh does) and configure again (cmake --preset release)");
  return Eigensolver::slepc;
}

bool parse_out_of_core(TomlReader& r, Eigensolver eigensolver) {
  const bool out_of_core = r.boolean("out_of_core", false);
  if (out_of_core && eigensolver != Eigensolver::slepc)
    r.fail("out_of_core",
           "needs eigensolver = \"slepc\" (MUMPS keeps its factors on disk; the default eigensolver's CHOLMOD "
           "factor stays in memory)");
  return out_of_core;
}

}  // namespace bb
