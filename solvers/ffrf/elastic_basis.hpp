// Elastic coordinates of a rotating body: every free nodal DOF (q = eta), or a modal basis
// q = Phi eta of fixed-interface (root-clamped) modes at rest, the reduction SAMS/2000 uses
// (thesis section 2.1.3.1, eq 2.14: "the number of elastic coordinates can be chosen"), optionally
// with a selection of modes and with static correction shapes. The body's operators projected on
// the basis are what the integrator and the rotating modal solver work with. SI units.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "ffrf/coordinate_algebra.hpp"
#include "ffrf/rotating_body.hpp"

namespace bb::ffrf {

enum class BasisKind {
  nodal,  // every free DOF: exact, sparse operators
  modal,  // the lowest fixed-interface modes at rest (plus static shapes): dense, small
};

struct ElasticBasisOptions {
  BasisKind kind = BasisKind::nodal;
  int n_modes = 0;                  // modal: compute the first n modes at rest (n >= 1)
  std::vector<int> selected_modes;  // modal: 1-based mode numbers kept among those n; empty = all n
  // modal: append the static responses K^-1 f_c, K^-1 f_alpha and K^-1 of the gravity loads
  // (Craig's "modal truncation augmentation"), M-orthonormalized against the modes. The centrifugal
  // deflection is mostly a stretch that the low bending modes cannot represent; with these shapes
  // K q = f is solved exactly in the basis for each of these loads, and the spin-softened,
  // stiffened static deflection to the accuracy of a Rayleigh-Ritz approximation
  // (tests/unit/ffrf_elastic_basis_test.cpp measures both).
  bool static_correction = true;
};

struct ElasticBasis {
  BasisKind kind = BasisKind::nodal;
  Eigen::MatrixXd shapes;          // modal: n_free x size, M-orthonormal columns; nodal: empty
  Eigen::VectorXd frequencies_hz;  // modal: of the kept modes at rest (static shapes excluded)
  std::vector<int> mode_numbers;   // modal: 1-based numbers of the kept modes
  int static_shapes = 0;           // modal: columns appended by static_correction
  int n_free = 0;

  int size() const { return kind == BasisKind::nodal ? n_free : static_cast<int>(shapes.cols()); }
};

// Throws InputError for an empty basis, n_modes >= free DOFs ("a basis larger than the body"),
// or a selected mode number outside 1..n_modes; SolverError when the modes cannot be computed.
ElasticBasis make_elastic_basis(const RotatingBody& body, const ElasticBasisOptions& options);

// The body's operators in the basis's coordinates eta (q = Phi eta): A_r = Phi^T A Phi, f_r = Phi^T f.
struct ProjectedBody {
  CoordinateMatrix mass, stiffness, projected_mass, gyroscopic, geometric_stiffness;
  Eigen::VectorXd centrifugal_load, euler_load;
  Eigen::MatrixXd gravity_load;  // size x dim
  MassProperties mass_properties;
  int dim = 2;
  double size = 0.0;  // body size [m], for the divergence bound
  const RotatingBody* body = nullptr;
  const ElasticBasis* basis = nullptr;

  int n() const { return static_cast<int>(centrifugal_load.size()); }
};

// The returned object refers to body and basis: both must outlive it.
ProjectedBody project(const RotatingBody& body, const ElasticBasis& basis);

// Free-DOF displacement q from basis coordinates eta (and the reverse projection of a free-DOF load).
Eigen::VectorXd to_free_dofs(const ElasticBasis& basis, const Eigen::VectorXd& eta);
Eigen::VectorXd load_in_basis(const ElasticBasis& basis, const Eigen::VectorXd& free_load);

// Rows of q = Phi eta for the given global DOFs (a constrained DOF gives a zero row): recovery of
// a few nodal displacements per time step without forming q.
Eigen::MatrixXd recovery_rows(const RotatingBody& body, const ElasticBasis& basis, const std::vector<int>& global_dofs);

}  // namespace bb::ffrf
