// A deformable body (FE mesh, 2D plane stress or 3D solid) clamped at its root to a rigid rotor that
// turns about a fixed axis, in the floating frame of reference (Shabana, Dynamics of Multibody
// Systems; thesis section 2.1.3, eqs 2.11-2.31). The body frame is the rotor frame (it coincides
// with the inertial frame at theta = 0); the model's constrained DOFs are the root (reference
// conditions: clamped root), so the elastic coordinates are the free nodal DOFs. SI units.
//
// With u = S q the elastic displacement in the rotating frame, y = x - p + u (p a point of the
// axis a), the inertial-frame kinetic energy T = 1/2 integral rho |Omega a x y + u'|^2 dV
// (thesis eqs 2.12, 2.15) is, on the free DOFs,
//   T = 1/2 q'^T M q' + Omega q'^T (g0 + G q) + 1/2 Omega^2 (J0 + 2 q^T f_c + q^T M_p q),
// g0 = G (x - p) = -f_alpha, and Lagrange's equations for q with a prescribed rotation theta(t)
// (Omega = theta', alpha = theta'') give the thesis's eq 2.31 for the elastic coordinates:
//   M q'' + 2 Omega G q' + (K - Omega^2 M_p + alpha G) q = Omega^2 f_c + alpha f_alpha + f_g + f_ext.
// The matrices below are the operators of that equation, restricted to the free DOFs.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "assembly/dof_map.hpp"
#include "model/model.hpp"

namespace bb::ffrf {

struct RotationAxis {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit vector; in 2D +z or -z
  Eigen::Vector3d point = Eigen::Vector3d::Zero();       // a point of the axis [m] (2D: z ignored)
};

struct MassProperties {
  double mass = 0.0;             // [kg]
  Eigen::VectorXd first_moment;  // integral rho (x - p) dV, body frame, dim entries [kg m]
  double axis_inertia = 0.0;     // J0 = integral rho |P (x - p)|^2 dV, undeformed [kg m^2]
};

struct RotatingBody {
  int dim = 2;
  RotationAxis axis;
  DofMap dofs;
  Eigen::VectorXd positions;  // undeformed nodal coordinates, all DOFs (node * dim + dir) [m]

  // Free x free, all on one sparse pattern (ffrf/body_assembly).
  Eigen::SparseMatrix<double> mass;            // M [kg]
  Eigen::SparseMatrix<double> stiffness;       // K [N/m]
  Eigen::SparseMatrix<double> projected_mass;  // M_p: spin softening, M in 2D [kg]
  Eigen::SparseMatrix<double> gyroscopic;      // G, skew: Coriolis 2 Omega G, Euler alpha G [kg]
  // K_sigma1: initial-stress stiffness of the stresses of u1 (K u1 = f_c, the pre-stress at unit
  // speed), so that the centrifugal pre-stress stiffness is Omega^2 K_sigma1 [N/m per (rad/s)^2].
  // Spin softening is left out of this solve on purpose: the pre-stress is then exactly linear in
  // Omega^2 (one matrix for every speed), and what it drops is O(rho Omega^2 L^2 / E) relative to
  // the stress (1.3e-4 for the thesis blade at 300 rad/s; 1e-4 for the spin-up beam at 6 rad/s).
  Eigen::SparseMatrix<double> geometric_stiffness;

  Eigen::VectorXd centrifugal_load;       // f_c = M_p (x - p) restricted to free rows, per unit Omega^2 [kg m]
  Eigen::VectorXd euler_load;             // f_alpha = -G (x - p), per unit alpha [kg m]
  Eigen::MatrixXd gravity_load;           // n_free x dim: f_g = gravity_load * g_body [kg]
  Eigen::VectorXd unit_speed_deflection;  // u1 [m s^2]
  MassProperties mass_properties;
  double size = 0.0;  // diagonal of the undeformed bounding box [m]

  int n_free() const { return dofs.n_free; }
};

// Builds every operator from the model's mesh, section and constraints. Throws InputError when the
// axis is not a unit vector (or not +-z in 2D), the density is not positive, a constraint
// prescribes a non-zero displacement (the root is clamped to the rotor), nothing is free, or the
// constraints do not hold the body (K singular).
RotatingBody build_rotating_body(const Model& model, const RotationAxis& axis = {});

// Rotation of the body frame about the axis by theta, dim x dim (Rodrigues: I + sin a~ + (1 - cos) a~^2).
Eigen::MatrixXd axis_rotation(const RotatingBody& body, double theta);
// d/dtheta and d2/dtheta2 of axis_rotation.
Eigen::MatrixXd axis_rotation_derivative(const RotatingBody& body, double theta, int order);

// All-DOF displacement (constrained DOFs zero) from free-DOF values, and the free rows of an
// all-DOF vector (e.g. assembly/assemble's load_vector(model), for FfrfOptions::external_load).
Eigen::VectorXd expand_to_global(const RotatingBody& body, const Eigen::VectorXd& free_values);
Eigen::VectorXd restrict_to_free(const RotatingBody& body, const Eigen::VectorXd& global_values);

}  // namespace bb::ffrf
