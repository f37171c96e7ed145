#include "cyclic/cyclic_campbell.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "common/parallel_indices.hpp"
#include "ffrf/body_assembly.hpp"
#include "linalg/spd_factor.hpp"

namespace bb {

CyclicCampbell cyclic_campbell(const Model& model, const FreeSystem& sector, const CyclicDofs& cyclic,
                               const std::vector<double>& speeds, const std::vector<int>& nodal_diameters, int families,
                               const ModalOptions& options, size_t workers) {
  if (!(model.section.density > 0))
    throw InputError("cyclic Campbell diagram: the centrifugal load needs material.rho > 0");
  const Mesh& mesh = model.mesh;
  const DofMap& dofs = sector.dofs;
  const ffrf::InertiaOperators inertia = ffrf::assemble_inertia(mesh, model.section, Eigen::Vector3d::UnitZ());
  const Eigen::SparseMatrix<double> spin = partition(inertia.projected_mass, dofs).ff;
  // Centrifugal load per unit Omega^2 about the z axis through the origin: M_p x.
  Eigen::VectorXd positions(static_cast<Eigen::Index>(mesh.n_nodes()) * mesh.dim);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    for (int d = 0; d < mesh.dim; ++d) positions[n * mesh.dim + d] = mesh.coords(n, d);
  const Eigen::VectorXd load = free_part(dofs, inertia.projected_mass * positions);
  // In phase (ND 0) the sector's faces are tied by the rotation: the deflection every sector shares.
  const CyclicProjection in_phase = cyclic_projection(dofs.n_free, cyclic, 0);
  SpdFactorization factor(ordering_for_dimension(mesh.dim));
  const FactorStatus status = factor.factorize(project(sector.stiffness, in_phase));
  if (!status.ok)
    throw SolverError(fmt::format("cyclic Campbell diagram: the in-phase static problem: {}", status.message));
  const Eigen::VectorXd u1 = in_phase.T * factor.solve(Eigen::VectorXd(in_phase.T.transpose() * load));
  const Eigen::SparseMatrix<double> stress =
      partition(ffrf::assemble_geometric_stiffness(mesh, model.section, to_global(dofs, u1, false)), dofs).ff;
  CyclicCampbell c;
  c.speeds = speeds;
  c.nodal_diameters = nodal_diameters;
  c.max_unit_speed_deflection = u1.cwiseAbs().maxCoeff();
  for (size_t d = 0; d < nodal_diameters.size(); ++d)
    c.frequencies_hz.push_back(Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(speeds.size()), families));
  std::vector<Eigen::SparseMatrix<double>> stiffness;
  for (const double speed : speeds) stiffness.push_back(sector.stiffness + speed * speed * (stress - spin));
  // Every (speed, nodal diameter) pair is its own eigenproblem.
  const size_t nd = nodal_diameters.size();
  for_each_index(speeds.size() * nd, workers, [&](size_t job) {
    const size_t s = job / nd, d = job % nd;
    const NodalDiameterModes m =
        nodal_diameter_modes(stiffness[s], sector.mass, cyclic, nodal_diameters[d], families, options);
    c.frequencies_hz[d].row(static_cast<Eigen::Index>(s)) = m.frequencies_hz.head(families).transpose();
  });
  return c;
}

int excited_nodal_diameter(int engine_order, int sectors) {
  const int k = engine_order % sectors;
  return std::min(k, sectors - k);
}

std::vector<CyclicCrossing> engine_order_crossings(const CyclicCampbell& c, const std::vector<int>& engine_orders,
                                                   int sectors) {
  std::vector<CyclicCrossing> out;
  for (int eo : engine_orders) {
    const int k = excited_nodal_diameter(eo, sectors);
    const auto it = std::find(c.nodal_diameters.begin(), c.nodal_diameters.end(), k);
    if (it == c.nodal_diameters.end()) continue;
    const Eigen::MatrixXd& f = c.frequencies_hz[static_cast<size_t>(it - c.nodal_diameters.begin())];
    for (Eigen::Index m = 0; m < f.cols(); ++m)
      for (size_t s = 0; s + 1 < c.speeds.size(); ++s) {
        // g = f - EO Omega / 2 pi changes sign between two speeds: the line crosses the family there.
        const auto g = [&](size_t i) {
          return f(static_cast<Eigen::Index>(i), m) - eo * c.speeds[i] / (2 * std::numbers::pi);
        };
        const double g0 = g(s), g1 = g(s + 1);
        if (g0 == 0.0 || g0 * g1 < 0.0) {
          const double t = g0 == 0.0 ? 0.0 : g0 / (g0 - g1);
          const double speed = c.speeds[s] + t * (c.speeds[s + 1] - c.speeds[s]);
          out.push_back({eo, k, static_cast<int>(m) + 1, speed, eo * speed / (2 * std::numbers::pi)});
        }
      }
  }
  return out;
}

}  // namespace bb
