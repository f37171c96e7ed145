#include "cyclic/cyclic_modes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "linalg/inertia.hpp"

namespace bb {

NodalDiameterModes nodal_diameter_modes(const Eigen::SparseMatrix<double>& stiffness,
                                        const Eigen::SparseMatrix<double>& mass, const CyclicDofs& cyclic,
                                        int nodal_diameter, int families, const ModalOptions& base) {
  const auto t0 = std::chrono::steady_clock::now();
  const CyclicProjection p = cyclic_projection(static_cast<int>(stiffness.rows()), cyclic, nodal_diameter);
  const int multiplicity = p.split ? 2 : 1;
  ModalOptions options = base;
  options.n_modes = multiplicity * families;
  if (options.n_modes >= p.reduced_size())
    throw InputError(fmt::format("nodal diameter {}: asked for {} families of a sector problem with {} unknowns",
                                 nodal_diameter, families, p.reduced_size() / multiplicity));
  const ModalSolution sol = lowest_modes(project(stiffness, p), project(mass, p), options);
  NodalDiameterModes out;
  out.nodal_diameter = nodal_diameter;
  out.pairs = p.split;
  out.reduced_size = static_cast<int>(p.reduced_size());
  out.iterations = sol.iterations;
  out.lanczos_runs = sol.lanczos_runs;
  out.max_residual = sol.max_residual;
  out.sturm_frequency_hz = std::sqrt(std::max(sol.sturm_shift, 0.0)) / (2 * std::numbers::pi);
  if (sol.sturm_count >= 0) {
    if (sol.sturm_count % multiplicity != 0)
      throw SolverError(
          fmt::format("nodal diameter {}: the Sturm count of the cosine/sine problem is odd ({}): its "
                      "pairs are broken",
                      nodal_diameter, sol.sturm_count));
    out.sturm_count = sol.sturm_count / multiplicity;
  }
  // Each pair's two members are equal up to rounding: the first stands for both.
  const Eigen::Index n = sol.eigenvalues.size() / multiplicity;
  out.frequencies_hz.resize(n);
  const Eigen::Index sector = p.n_free;
  out.cosine.resize(sector, n);
  out.sine = Eigen::MatrixXd::Zero(sector, n);
  for (Eigen::Index f = 0; f < n; ++f) {
    const Eigen::Index col = multiplicity * f;
    out.frequencies_hz[f] = std::sqrt(std::max(sol.eigenvalues[col], 0.0)) / (2 * std::numbers::pi);
    const Eigen::VectorXd wave = p.T * sol.shapes.col(col);
    out.cosine.col(f) = wave.head(sector);
    if (p.split) out.sine.col(f) = wave.tail(sector);
  }
  out.seconds = seconds_since(t0);
  return out;
}

Eigen::Index common_families(const std::vector<NodalDiameterModes>& diameters) {
  Eigen::Index families = diameters.empty() ? 0 : diameters.front().frequencies_hz.size();
  for (const NodalDiameterModes& nd : diameters) families = std::min(families, nd.frequencies_hz.size());
  return families;
}

int nodal_diameter_count(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                         const CyclicDofs& cyclic, int nodal_diameter, double frequency_hz) {
  const CyclicProjection p = cyclic_projection(static_cast<int>(stiffness.rows()), cyclic, nodal_diameter);
  const InertiaCount c =
      eigenvalues_below(project(stiffness, p), project(mass, p), std::pow(2 * std::numbers::pi * frequency_hz, 2));
  if (!c.ok || (p.split && c.negative % 2 != 0)) return -1;
  return p.split ? c.negative / 2 : c.negative;
}

}  // namespace bb
