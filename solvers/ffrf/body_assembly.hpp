// Global matrices of a deformable body for the floating-frame equations, all on the one nodal
// pattern of assembly/sparsity (so that the FFRF solvers combine them by value arrays): the
// inertia operators of a rotation about a fixed axis and the initial-stress stiffness of a
// displacement field. All DOFs, global order node * dim + dir. SI units.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "model/model.hpp"

namespace bb::ffrf {

// With m_ab = integral rho N_a N_b dV (the consistent mass's scalar part), a the unit axis,
// P = I - a a^T and a~ the cross-product matrix of a (a~ y = a x y):
//   M   = m (x) I     integral rho S^T S dV            (thesis eq 2.58/2.39)
//   M_p = m (x) P     integral rho S^T P S dV          (spin softening, centrifugal load)
//   G   = m (x) a~    integral rho S^T a~ S dV, skew   (Coriolis and Euler terms)
// (Shabana, Dynamics of Multibody Systems, 3rd ed., sec. 5.4: the inertia shape integrals of a
// rotation about a fixed axis). In 2D the axis is +z or -z: P = I and a~ = a_z [[0, -1], [1, 0]].
struct InertiaOperators {
  Eigen::SparseMatrix<double> mass;
  Eigen::SparseMatrix<double> projected_mass;
  Eigen::SparseMatrix<double> gyroscopic;
};

// Throws InputError naming an element with invalid geometry.
InertiaOperators assemble_inertia(const Mesh& mesh, const fe::PlaneSection& section,
                                  const Eigen::Vector3d& axis_direction);

// K_sigma of the stresses of the displacement field u (all DOFs), element by element from
// fe/initial_stress. Throws InputError naming an element with invalid geometry.
Eigen::SparseMatrix<double> assemble_geometric_stiffness(const Mesh& mesh, const fe::PlaneSection& section,
                                                         const Eigen::VectorXd& u);

}  // namespace bb::ffrf
