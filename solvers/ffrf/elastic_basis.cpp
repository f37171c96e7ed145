#include "ffrf/elastic_basis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "linalg/dense_eigen.hpp"
#include "linalg/modal_solver.hpp"
#include "linalg/spd_factor.hpp"

namespace bb::ffrf {
namespace {

// Below this many free DOFs (or when most modes are wanted) a dense generalized eigensolver is
// cheaper and more robust than shift-invert Lanczos, which also needs n_modes < n_free.
constexpr int kDenseEigenLimit = 400;

void validate(const RotatingBody& body, const ElasticBasisOptions& o) {
  if (o.kind == BasisKind::nodal) {
    if (o.n_modes != 0 || !o.selected_modes.empty())
      throw InputError("elastic basis: n_modes and selected_modes apply to a modal basis, not to the nodal one");
    return;
  }
  if (o.n_modes < 1)
    throw InputError(
        fmt::format("modal elastic basis needs n_modes >= 1, got {} (an empty basis has no elastic "
                    "coordinates)",
                    o.n_modes));
  if (o.n_modes > body.n_free())
    throw InputError(
        fmt::format("modal elastic basis of {} modes is larger than the body's {} free DOFs: ask for at "
                    "most {} modes, or use the nodal basis",
                    o.n_modes, body.n_free(), body.n_free()));
  for (int m : o.selected_modes)
    if (m < 1 || m > o.n_modes)
      throw InputError(fmt::format("modal elastic basis: selected mode {} is outside 1..{} (n_modes)", m, o.n_modes));
}

struct Modes {
  Eigen::MatrixXd shapes;       // mass-normalized columns
  Eigen::VectorXd eigenvalues;  // omega^2
};

Modes modes_at_rest(const RotatingBody& body, int n_modes) {
  const int n = body.n_free();
  if (n <= kDenseEigenLimit || 2 * n_modes > n) {
    const Eigen::MatrixXd k(body.stiffness), m(body.mass);
    const DenseEigen<double> eig = symmetric_eigen(k, m);
    if (!eig.ok) throw SolverError("modal elastic basis: dense eigensolver failed");
    return {eig.vectors.leftCols(n_modes), eig.values.head(n_modes)};
  }
  ModalOptions options;
  options.n_modes = n_modes;
  options.ordering = ordering_for_dimension(body.dim);
  const ModalSolution s = lowest_modes(body.stiffness, body.mass, options);
  return {s.shapes, s.eigenvalues};
}

// Appends the M-orthonormal part of K^-1 f for each load f (two Gram-Schmidt passes); a shape the
// basis already spans (relative remainder < 1e-8) is dropped.
int append_static_shapes(const RotatingBody& body, Eigen::MatrixXd& shapes) {
  SpdFactorization factor(ordering_for_dimension(body.dim));
  if (!factor.factorize(body.stiffness).ok) throw SolverError("modal elastic basis: stiffness cannot be factored");
  std::vector<Eigen::VectorXd> loads{body.centrifugal_load, body.euler_load};
  for (Eigen::Index d = 0; d < body.gravity_load.cols(); ++d) loads.push_back(body.gravity_load.col(d));
  int added = 0;
  for (const Eigen::VectorXd& f : loads) {
    Eigen::VectorXd v = factor.solve(f);
    const double norm0 = std::sqrt(v.dot(body.mass * v));
    if (!(norm0 > 0.0)) continue;
    for (int pass = 0; pass < 2; ++pass) v -= shapes * (shapes.transpose() * (body.mass * v));
    const double norm = std::sqrt(v.dot(body.mass * v));
    if (!(norm > 1e-8 * norm0)) continue;
    shapes.conservativeResize(Eigen::NoChange, shapes.cols() + 1);
    shapes.col(shapes.cols() - 1) = v / norm;
    ++added;
  }
  return added;
}

CoordinateMatrix projected(const SparseMatrix& a, const ElasticBasis& basis, bool skew) {
  if (basis.kind == BasisKind::nodal) return CoordinateMatrix(SparseMatrix(a));
  const Eigen::MatrixXd ap = a * basis.shapes;
  Eigen::MatrixXd r = basis.shapes.transpose() * ap;
  r = skew ? Eigen::MatrixXd(0.5 * (r - r.transpose())) : Eigen::MatrixXd(0.5 * (r + r.transpose()));
  return CoordinateMatrix(std::move(r));
}

}  // namespace

ElasticBasis make_elastic_basis(const RotatingBody& body, const ElasticBasisOptions& options) {
  validate(body, options);
  ElasticBasis basis;
  basis.kind = options.kind;
  basis.n_free = body.n_free();
  if (options.kind == BasisKind::nodal) return basis;

  const Modes modes = modes_at_rest(body, options.n_modes);
  std::vector<int> keep = options.selected_modes;
  if (keep.empty())
    for (int m = 1; m <= options.n_modes; ++m) keep.push_back(m);
  std::sort(keep.begin(), keep.end());
  keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
  basis.shapes.resize(body.n_free(), static_cast<Eigen::Index>(keep.size()));
  basis.frequencies_hz.resize(static_cast<Eigen::Index>(keep.size()));
  for (size_t i = 0; i < keep.size(); ++i) {
    const Eigen::Index col = keep[i] - 1, ii = static_cast<Eigen::Index>(i);
    basis.shapes.col(ii) = modes.shapes.col(col);
    basis.frequencies_hz[ii] = std::sqrt(std::max(modes.eigenvalues[col], 0.0)) / (2.0 * std::numbers::pi);
  }
  basis.mode_numbers = keep;
  if (options.static_correction) basis.static_shapes = append_static_shapes(body, basis.shapes);
  return basis;
}

ProjectedBody project(const RotatingBody& body, const ElasticBasis& basis) {
  if (basis.n_free != body.n_free()) throw std::invalid_argument("project: basis made for another body");
  ProjectedBody p;
  p.mass = projected(body.mass, basis, false);
  p.stiffness = projected(body.stiffness, basis, false);
  p.projected_mass = projected(body.projected_mass, basis, false);
  p.gyroscopic = projected(body.gyroscopic, basis, true);
  p.geometric_stiffness = projected(body.geometric_stiffness, basis, false);
  p.centrifugal_load = load_in_basis(basis, body.centrifugal_load);
  p.euler_load = load_in_basis(basis, body.euler_load);
  p.gravity_load = basis.kind == BasisKind::nodal ? body.gravity_load
                                                  : Eigen::MatrixXd(basis.shapes.transpose() * body.gravity_load);
  p.mass_properties = body.mass_properties;
  p.dim = body.dim;
  p.size = body.size;
  p.body = &body;
  p.basis = &basis;
  return p;
}

Eigen::VectorXd to_free_dofs(const ElasticBasis& basis, const Eigen::VectorXd& eta) {
  return basis.kind == BasisKind::nodal ? eta : Eigen::VectorXd(basis.shapes * eta);
}

Eigen::VectorXd load_in_basis(const ElasticBasis& basis, const Eigen::VectorXd& free_load) {
  return basis.kind == BasisKind::nodal ? free_load : Eigen::VectorXd(basis.shapes.transpose() * free_load);
}

Eigen::MatrixXd recovery_rows(const RotatingBody& body, const ElasticBasis& basis,
                              const std::vector<int>& global_dofs) {
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(global_dofs.size()), basis.size());
  for (size_t i = 0; i < global_dofs.size(); ++i) {
    const int g = global_dofs[i];
    if (g < 0 || g >= body.dofs.n_global())
      throw InputError(
          fmt::format("output DOF {} is outside 0..{} (node * dim + direction)", g, body.dofs.n_global() - 1));
    const int eq = body.dofs.equation[static_cast<size_t>(g)];
    if (eq < 0) continue;  // constrained: clamped to the rotor, zero
    const Eigen::Index r = static_cast<Eigen::Index>(i);
    if (basis.kind == BasisKind::nodal) {
      rows(r, eq) = 1.0;
    } else {
      rows.row(r) = basis.shapes.row(eq);
    }
  }
  return rows;
}

}  // namespace bb::ffrf
