// Stresses at the integration points of an element from its nodal displacements (any displacement
// field: pre-stress, stress recovery), and the initial-stress (geometric) stiffness of a stress
// field given at those points. Pure functions like fe/solid.hpp and fe/plane_stress.hpp. SI units.
//
// Integration points are those of each element's stiffness rule, xi fastest then eta then zeta:
// q4 2x2 Gauss, cst 1 point (centroid), hex8 and hex8i 2x2x2 Gauss, hex20 3x3x3 Gauss. Stresses
// are columns: plane stress (sxx, syy, sxy) [Pa]; solids Voigt (xx, yy, zz, xy, yz, zx) [Pa].
//
// Geometric stiffness (e.g. Cook, Malkus, Plesha & Witt, Concepts and Applications of FEA, 4th ed.,
// sec. 18.2; Bathe, Finite Element Procedures, eq. 6.62): the work of a fixed stress sigma_0 on the
// nonlinear part of the Green strain, 1/2 sum_i grad(u_i)^T sigma_0 grad(u_i), gives
//   K_sigma[(a, i), (b, k)] = delta_ik integral grad(N_a)^T sigma_0 grad(N_b) dV,
// symmetric by construction; a rigid translation is in its null space for any sigma_0.
//
// hex8i (incompatible modes): the stresses include the condensed bubble strains (alpha =
// -K_aa^-1 K_au u, the same Wilson-Taylor modes as fe/solid.cpp), so bending stresses are as
// accurate as the element's stiffness. The geometric stiffness uses the compatible trilinear
// field only (hex8_geometric_stiffness with these stresses): the bubbles are element-internal
// strain enhancements condensed with K alone; carrying them into K_sigma would make the condensation
// depend on the pre-stress (a new condensation per speed) for a second-order gain, since the
// rotations that the pre-stress stiffens are those of the compatible field (the bubbles' average
// gradient over the element vanishes by Taylor's correction).
#pragma once
#include <Eigen/Dense>

#include "fe/plane_stress.hpp"
#include "fe/solid.hpp"

namespace bb::fe {

using Q4PointStresses = Eigen::Matrix<double, 3, 4>;
using CstPointStresses = Eigen::Matrix<double, 3, 1>;
using Hex8PointStresses = Eigen::Matrix<double, 6, 8>;
using Hex20PointStresses = Eigen::Matrix<double, 6, 27>;

// Physical coordinates of the integration points, one column per point [m].
Eigen::Matrix<double, 2, 4> q4_integration_points(const Q4Coords& xy);
Eigen::Matrix<double, 2, 1> cst_integration_points(const CstCoords& xy);
Eigen::Matrix<double, 3, 8> hex8_integration_points(const Hex8Coords& xyz);
Eigen::Matrix<double, 3, 27> hex20_integration_points(const Hex20Coords& xyz);

// sigma = D B u at every integration point. Throw std::domain_error on a non-positive Jacobian.
Q4PointStresses q4_point_stresses(const Q4Coords& xy, const Eigen::Matrix<double, 8, 1>& u,
                                  const PlaneSection& section);
CstPointStresses cst_point_stresses(const CstCoords& xy, const Eigen::Matrix<double, 6, 1>& u,
                                    const PlaneSection& section);
Hex8PointStresses hex8_point_stresses(const Hex8Coords& xyz, const Eigen::Matrix<double, 24, 1>& u,
                                      const SolidMaterial& material);
Hex8PointStresses hex8_incompatible_point_stresses(const Hex8Coords& xyz, const Eigen::Matrix<double, 24, 1>& u,
                                                   const SolidMaterial& material);
Hex20PointStresses hex20_point_stresses(const Hex20Coords& xyz, const Eigen::Matrix<double, 60, 1>& u,
                                        const SolidMaterial& material);

// K_sigma of a stress given at the integration points (the order above). Plane stress integrates
// over the thickness t (in-plane displacement gradients only). hex8i uses hex8_geometric_stiffness.
Matrix8 q4_geometric_stiffness(const Q4Coords& xy, const Q4PointStresses& stress, double thickness);
Matrix6 cst_geometric_stiffness(const CstCoords& xy, const CstPointStresses& stress, double thickness);
Matrix24 hex8_geometric_stiffness(const Hex8Coords& xyz, const Hex8PointStresses& stress);
Matrix60 hex20_geometric_stiffness(const Hex20Coords& xyz, const Hex20PointStresses& stress);

}  // namespace bb::fe
