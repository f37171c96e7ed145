#include "cyclic/cyclic_modes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <type_traits>

#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "linalg/inertia.hpp"

namespace bb {

namespace {

// Frequencies [Hz] of eigenvalues w^2.
Eigen::VectorXd frequencies_hz(const Eigen::VectorXd& eigenvalues) {
  return eigenvalues.array().max(0.0).sqrt() / (2 * std::numbers::pi);
}

// solve(K_k, M_k, T) on nodal diameter k's problem: the real projection for k = 0 and N/2, the
// complex Hermitian one between (the travelling wave's amplitude, each eigenvalue once; its real
// and imaginary parts are the standing cosine and sine waves). Refuses k outside 0..N/2.
template <class Solve>
auto solve_projected(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                     const CyclicDofs& cyclic, int nodal_diameter, const Solve& solve) {
  const int n_free = static_cast<int>(stiffness.rows());
  const CyclicProjection p = cyclic_projection(n_free, cyclic, nodal_diameter);
  if (!p.split) return solve(project(stiffness, p), project(mass, p), p.T);
  const Eigen::SparseMatrix<std::complex<double>> T =
      complex_cyclic_projection(n_free, cyclic, 2 * std::numbers::pi * nodal_diameter / cyclic.sectors);
  return solve(project(stiffness, T), project(mass, T), T);
}

}  // namespace

NodalDiameterModes nodal_diameter_modes(const Eigen::SparseMatrix<double>& stiffness,
                                        const Eigen::SparseMatrix<double>& mass, const CyclicDofs& cyclic,
                                        int nodal_diameter, int families, const ModalOptions& base) {
  const auto t0 = std::chrono::steady_clock::now();
  ModalOptions options = base;
  options.n_modes = families;
  NodalDiameterModes out;
  out.nodal_diameter = nodal_diameter;
  solve_projected(stiffness, mass, cyclic, nodal_diameter, [&](const auto& k, const auto& m, const auto& T) {
    const bool travelling = Eigen::NumTraits<typename std::decay_t<decltype(T)>::Scalar>::IsComplex;
    if (families >= T.cols())
      throw InputError(fmt::format("nodal diameter {}: asked for {} families of a sector problem with {} unknowns",
                                   nodal_diameter, families, T.cols()));
    const auto sol = lowest_modes(k, m, options);
    out.pairs = travelling;
    out.reduced_size = static_cast<int>((travelling ? 2 : 1) * T.cols());
    out.iterations = sol.iterations;
    out.lanczos_runs = sol.lanczos_runs;
    out.max_residual = sol.max_residual;
    out.sturm_count = sol.sturm_count;
    out.sturm_frequency_hz = std::sqrt(std::max(sol.sturm_shift, 0.0)) / (2 * std::numbers::pi);
    out.frequencies_hz = frequencies_hz(sol.eigenvalues);
    const auto waves = (T * sol.shapes).eval();
    out.cosine = waves.real();
    out.sine = waves.imag();
  });
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
  const double sigma = std::pow(2 * std::numbers::pi * frequency_hz, 2);
  const InertiaCount c =
      solve_projected(stiffness, mass, cyclic, nodal_diameter,
                      [&](const auto& k, const auto& m, const auto&) { return eigenvalues_below(k, m, sigma); });
  return c.ok ? c.negative : -1;
}

}  // namespace bb
