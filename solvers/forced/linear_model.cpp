#include "forced/linear_model.hpp"

#include <fmt/format.h>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "reduction/cached_craig_bampton.hpp"
#include "reduction/reduced_model_io.hpp"

namespace bb {

int node_of_point(const Model& model, const std::string& point) {
  const auto it = model.node_sets.find(point);
  if (it == model.node_sets.end())
    throw InputError(fmt::format("'analysis': point '{}' is not a node set of the model", point));
  if (it->second.size() != 1)
    throw InputError(
        fmt::format("'analysis': point '{}' must be a set of exactly one node, it has {}", point, it->second.size()));
  return it->second.front();
}

int free_index(const Model& model, const FreeSystem& system, const PointDof& dof) {
  const int global = node_of_point(model, dof.point) * model.mesh.dim + dof.direction;
  const int eq = system.dofs.equation[static_cast<size_t>(global)];
  if (eq < 0)
    throw InputError(fmt::format("'analysis': {} is constrained; a force or response needs a free DOF", dof.name()));
  return eq;
}

RayleighCoefficients rayleigh_of(const FrfDamping& d) {
  return fit_rayleigh(kTwoPi * d.rayleigh_hz[0], d.rayleigh_zeta[0], kTwoPi * d.rayleigh_hz[1], d.rayleigh_zeta[1]);
}

ReducedModel build_reduced_model(const Model& model, const FreeSystem& system, const RomSpec& rom,
                                 CraigBamptonTiming* timing, const ModelCacheSettings* cache) {
  if (!rom.file.empty()) return read_reduced_model(rom.file);
  if (rom.matrices) return *rom.matrices;
  std::vector<int> masters;
  std::vector<ReducedDof> names;
  for (const std::string& point : rom.masters)
    for (Direction d = 0; d < model.mesh.dim; ++d) {
      masters.push_back(free_index(model, system, {point, d}));
      names.push_back({point, d, 0});
    }
  CraigBamptonOptions options;
  options.n_modes = rom.modes;
  options.modes_below_hz = rom.modes_below_hz;
  options.ordering = ordering_for_dimension(model.mesh.dim);
  options.eigensolver = rom.eigensolver;
  return cached_craig_bampton(system.stiffness, system.mass, masters, names, options, cache, timing);
}

Eigen::MatrixXd damping_matrix(const FrfDamping& damping, const ReducedModel& m) {
  if (damping.kind == FrfDamping::Kind::modal)
    return modal_damping_matrix(m.stiffness, m.mass, damping.modal_ratios(m.stiffness.rows()));
  const RayleighCoefficients c = rayleigh_of(damping);
  return c.alpha * m.mass + c.beta * m.stiffness;
}

}  // namespace bb
