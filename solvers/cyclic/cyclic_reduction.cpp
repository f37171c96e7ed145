#include "cyclic/cyclic_reduction.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "cyclic/cyclic_projection.hpp"
#include "linalg/dense_eigen.hpp"
#include "linalg/real_form.hpp"
#include "reduction/craig_bampton.hpp"

namespace bb {
namespace {

using Complex = std::complex<double>;
using Sparse = Eigen::SparseMatrix<double>;
using ComplexSparse = Eigen::SparseMatrix<Complex>;
using Eigen::Index;

Eigen::MatrixXcd hermitian_part(const Eigen::MatrixXcd& a) { return 0.5 * (a + a.adjoint()); }

// The complex vectors a + ib of the doubled problem's shapes (a; b), M-orthonormalized: a pair
// (a; b), (-b; a) stands for one complex vector (z and i z), so half of them drop out.
Eigen::MatrixXcd complex_modes(const Eigen::MatrixXd& shapes, const ComplexSparse& mass, Index wanted) {
  const Index m = shapes.rows() / 2;
  Eigen::MatrixXcd kept(m, wanted);
  Index n = 0;
  for (Index j = 0; j < shapes.cols() && n < wanted; ++j) {
    Eigen::VectorXcd z = shapes.col(j).head(m).cast<Complex>() + Complex(0.0, 1.0) * shapes.col(j).tail(m);
    const double before = std::sqrt(std::abs(z.dot(mass * z)));
    for (int pass = 0; pass < 2; ++pass)  // twice: Gram-Schmidt loses orthogonality once
      for (Index q = 0; q < n; ++q) z -= kept.col(q) * kept.col(q).dot(mass * z);
    const double after = std::sqrt(std::abs(z.dot(mass * z)));
    if (after > 1e-6 * before) kept.col(n++) = z / after;
  }
  if (n != wanted)
    throw SolverError(fmt::format(
        "cyclic Craig-Bampton: the doubled eigenproblem gave {} independent complex modes, {} expected", n, wanted));
  return kept;
}

}  // namespace

SectorReduction cyclic_craig_bampton(const Sparse& stiffness, const Sparse& mass, const CyclicDofs& cyclic,
                                     double phase, const std::vector<int>& masters, double cut_frequency_hz, int modes,
                                     const ModalOptions& options) {
  const int n = static_cast<int>(stiffness.rows());
  const std::vector<int> reduced = reduced_indices(n, cyclic);
  const ComplexSparse T = complex_cyclic_projection(n, cyclic, phase);
  const Index m = T.cols();
  std::vector<int> boundary;  // the masters' reduced indices, then again shifted into the imaginary half
  for (int dof : masters) {
    if (dof < 0 || dof >= n)
      throw InputError(fmt::format("cyclic Craig-Bampton: master free DOF {} out of range", dof));
    const int r = reduced[static_cast<size_t>(dof)];
    if (r < 0)
      throw InputError(
          fmt::format("cyclic Craig-Bampton: free DOF {} lies on the right cyclic face, which follows the left one; "
                      "choose a master off that face",
                      dof));
    boundary.push_back(r);
  }
  const Index nb = static_cast<Index>(boundary.size());
  for (Index i = 0; i < nb; ++i) boundary.push_back(boundary[static_cast<size_t>(i)] + static_cast<int>(m));

  const ComplexSparse k = project(stiffness, T), mc = project(mass, T);
  const Sparse kd = real_form(k), md = real_form(mc);
  int pairs = modes;
  if (cut_frequency_hz > 0.0) {
    const int count = fixed_interface_count(kd, md, boundary, cut_frequency_hz);
    if (count % 2 != 0)
      throw SolverError(fmt::format(
          "cyclic Craig-Bampton: {} doubled fixed-interface eigenvalues below {} Hz (odd: a pair is split by rounding)",
          count, cut_frequency_hz));
    pairs = count / 2;
  }
  CraigBamptonOptions cb;
  cb.n_modes = 2 * pairs;
  cb.ordering = options.ordering;
  cb.shift_frequency_hz = options.shift_frequency_hz;
  const ReducedModel real =
      craig_bampton(kd, md, boundary, std::vector<ReducedDof>(boundary.size(), ReducedDof{"master", -1, 0}), cb);

  Eigen::MatrixXcd basis(m, nb + pairs);
  const Eigen::MatrixXd& recovery = real.recovery;  // rows: (a; b) halves of the doubled problem
  for (Index i = 0; i < nb; ++i)
    basis.col(i) = recovery.col(i).head(m).cast<Complex>() + Complex(0.0, 1.0) * recovery.col(i).tail(m);
  SectorReduction out;
  out.phase = phase;
  out.masters = static_cast<int>(nb);
  out.mode_frequencies_hz.resize(pairs);
  if (pairs > 0) {
    Eigen::MatrixXcd q = complex_modes(recovery.rightCols(2 * pairs), mc, pairs);
    // Rayleigh-Ritz in their span: exact eigenvectors of the Hermitian problem, not mixtures of a pair.
    const Eigen::MatrixXcd kq = hermitian_part(q.adjoint() * (k * q)), mq = hermitian_part(q.adjoint() * (mc * q));
    const DenseEigen<std::complex<double>> ritz = symmetric_eigen(kq, mq);
    if (!ritz.ok) throw SolverError("cyclic Craig-Bampton: the Rayleigh-Ritz step failed");
    basis.rightCols(pairs) = q * ritz.vectors;
    out.mode_frequencies_hz = ritz.values.array().max(0.0).sqrt() / (2 * std::numbers::pi);
  }
  out.stiffness = hermitian_part(basis.adjoint() * (k * basis));
  out.mass = hermitian_part(basis.adjoint() * (mc * basis));
  return out;
}

}  // namespace bb
