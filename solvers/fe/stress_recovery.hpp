// Nodal values of an element's integration-point stresses, and the stress invariants an engineer
// reads (von Mises, principal stresses). Pure functions like the rest of fe/. SI units (Pa).
//
// Extrapolation (Hinton & Campbell, "Local and global smoothing of discontinuous finite element
// functions using a least squares method", IJNME 8, 1974; Cook, Malkus, Plesha & Witt, Concepts
// and Applications of FEA, 4th ed., sec. 7.6): the values at the points of the stiffness rule
// (fe/initial_stress.hpp, xi fastest) are interpolated by the polynomial those points determine
// uniquely, which is then evaluated at the element's nodes:
//   q4         bilinear through the 2x2 Gauss points (nodes at xi, eta = +-sqrt(3) in Gauss units)
//   cst        the one centroid value at every node
//   hex8/hex8i trilinear through the 2x2x2 Gauss points
//   hex20      triquadratic (27-point Lagrange) through the 3x3x3 Gauss points, at the 8 corners
//              and the 12 mid-edge nodes
// Each is exact for a field of that polynomial degree, in particular for a constant stress (the
// patch test), and each row of the matrix sums to 1.
#pragma once
#include <Eigen/Dense>

namespace bb::fe {

using Vector6 = Eigen::Matrix<double, 6, 1>;

// E (nodes x points): nodal value of node a = sum_p E(a, p) value at point p.
const Eigen::Matrix<double, 4, 4>& q4_extrapolation();
const Eigen::Matrix<double, 3, 1>& cst_extrapolation();
const Eigen::Matrix<double, 8, 8>& hex8_extrapolation();
const Eigen::Matrix<double, 20, 27>& hex20_extrapolation();

// Plane stress (sxx, syy, sxy), szz = 0: von Mises and the in-plane principal stresses s1 >= s2.
double von_mises_plane(const Eigen::Vector3d& s);
Eigen::Vector2d principal_plane(const Eigen::Vector3d& s);

// Solid, Voigt order (xx, yy, zz, xy, yz, zx): von Mises and the principal stresses s1 >= s2 >= s3.
double von_mises_solid(const Vector6& s);
Eigen::Vector3d principal_solid(const Vector6& s);

// Engineering strains from stresses of an isotropic material: plane stress (exx, eyy, gxy) and the
// thickness strain ezz = -nu (sxx + syy) / E; solids Voigt (exx, eyy, ezz, gxy, gyz, gzx).
Eigen::Vector4d plane_stress_strains(const Eigen::Vector3d& s, double youngs_modulus, double poisson_ratio);
Vector6 solid_strains(const Vector6& s, double youngs_modulus, double poisson_ratio);

}  // namespace bb::fe
