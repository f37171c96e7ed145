#include "assembly/free_system.hpp"

#include <chrono>

#include "assembly/assemble.hpp"

namespace bb {

FreeSystem assemble_free_system(const Model& model) {
  const auto t0 = std::chrono::steady_clock::now();
  FreeSystem s;
  s.dofs = number_dofs(model);
  const GlobalMatrices global = assemble(model.mesh, model.section);
  s.stiffness = partition(global.stiffness, s.dofs).ff;
  s.mass = partition(global.mass, s.dofs).ff;
  s.assembly_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace bb
