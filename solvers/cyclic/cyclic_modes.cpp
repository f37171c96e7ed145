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

namespace {

// Frequencies [Hz] of eigenvalues w^2.
Eigen::VectorXd frequencies_hz(const Eigen::VectorXd& eigenvalues) {
  return eigenvalues.array().max(0.0).sqrt() / (2 * std::numbers::pi);
}

}  // namespace

NodalDiameterModes nodal_diameter_modes(const Eigen::SparseMatrix<double>& stiffness,
                                        const Eigen::SparseMatrix<double>& mass, const CyclicDofs& cyclic,
                                        int nodal_diameter, int families, const ModalOptions& base) {
  const auto t0 = std::chrono::steady_clock::now();
  const int n_free = static_cast<int>(stiffness.rows());
  const CyclicProjection p = cyclic_projection(n_free, cyclic, nodal_diameter);
  ModalOptions options = base;
  options.n_modes = families;
  NodalDiameterModes out;
  out.nodal_diameter = nodal_diameter;
  out.pairs = p.split;
  auto record = [&](const auto& sol) {
    out.iterations = sol.iterations;
    out.lanczos_runs = sol.lanczos_runs;
    out.max_residual = sol.max_residual;
    out.sturm_count = sol.sturm_count;
    out.sturm_frequency_hz = std::sqrt(std::max(sol.sturm_shift, 0.0)) / (2 * std::numbers::pi);
    out.frequencies_hz = frequencies_hz(sol.eigenvalues);
  };
  auto refuse_small = [&](Eigen::Index unknowns) {
    if (families >= unknowns)
      throw InputError(fmt::format("nodal diameter {}: asked for {} families of a sector problem with {} unknowns",
                                   nodal_diameter, families, unknowns));
  };
  if (!p.split) {
    refuse_small(p.reduced_size());
    const ModalSolution sol = lowest_modes(project(stiffness, p), project(mass, p), options);
    record(sol);
    out.reduced_size = static_cast<int>(p.reduced_size());
    out.cosine = p.T * sol.shapes;
    out.sine = Eigen::MatrixXd::Zero(n_free, sol.shapes.cols());
  } else {
    // The travelling wave's complex amplitude: a Hermitian problem, each family once; its real
    // and imaginary parts are the standing cosine and sine waves.
    const Eigen::SparseMatrix<std::complex<double>> T =
        complex_cyclic_projection(n_free, cyclic, 2 * std::numbers::pi * nodal_diameter / cyclic.sectors);
    refuse_small(T.cols());
    const HermitianModalSolution sol = lowest_modes(project(stiffness, T), project(mass, T), options);
    record(sol);
    out.reduced_size = static_cast<int>(2 * T.cols());
    const Eigen::MatrixXcd waves = T * sol.shapes;
    out.cosine = waves.real();
    out.sine = waves.imag();
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
