// 3D solid element matrices, 3 translational DOFs per node. Pure functions: coordinates and
// material in, element matrices out. SI units. DOF order: (ux1, uy1, uz1, ux2, ...).
// Node order as in mesh/mesh.hpp (Ansys/CalculiX). Isoparametric; every function throws
// std::domain_error when the Jacobian determinant is not positive at an integration point
// (inverted, degenerate or wrongly ordered element).
#pragma once
#include <Eigen/Dense>

namespace bb::fe {

struct SolidMaterial {
  double youngs_modulus = 0.0;  // E [Pa]
  double poisson_ratio = 0.0;   // nu [-]
  double density = 0.0;         // rho [kg/m^3]
};

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Hex8Coords = Eigen::Matrix<double, 8, 3>;
using Hex20Coords = Eigen::Matrix<double, 20, 3>;
using Matrix24 = Eigen::Matrix<double, 24, 24>;
using Matrix60 = Eigen::Matrix<double, 60, 60>;

// Isotropic elasticity in Voigt order (xx, yy, zz, xy, yz, zx), engineering shear strains.
Matrix6 isotropic_elasticity(double youngs_modulus, double poisson_ratio);

// Trilinear hexahedron, 2x2x2 Gauss.
Matrix24 hex8_stiffness(const Hex8Coords& xyz, const SolidMaterial& material);
// Trilinear hexahedron enriched with Wilson's three incompatible bubble modes per direction,
// condensed statically, with Taylor's correction (bubble derivatives taken with the centre
// Jacobian) so that the element passes the patch test on distorted shapes. Removes the
// parasitic shear of hex8 in bending (Ansys SOLID45's default, KEYOPT(1)=0).
Matrix24 hex8_incompatible_stiffness(const Hex8Coords& xyz, const SolidMaterial& material);
Matrix24 hex8_consistent_mass(const Hex8Coords& xyz, const SolidMaterial& material);

// 20-node serendipity hexahedron, 3x3x3 Gauss.
Matrix60 hex20_stiffness(const Hex20Coords& xyz, const SolidMaterial& material);
Matrix60 hex20_consistent_mass(const Hex20Coords& xyz, const SolidMaterial& material);

// Shape functions N_a and their natural derivatives (rows d/dxi, d/deta, d/dzeta) at a natural
// point, node order as above: for other element formulas of fe/ (fe/initial_stress).
void hex8_shape_functions(const Eigen::Vector3d& natural, Eigen::Matrix<double, 8, 1>& n,
                          Eigen::Matrix<double, 3, 8>& dn);
void hex20_shape_functions(const Eigen::Vector3d& natural, Eigen::Matrix<double, 20, 1>& n,
                           Eigen::Matrix<double, 3, 20>& dn);

// Element volume (Gauss-integrated), for checks and mass reports.
double hex8_volume(const Hex8Coords& xyz);
double hex20_volume(const Hex20Coords& xyz);

}  // namespace bb::fe
