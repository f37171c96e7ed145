// Plane-stress element matrices (thesis eqs 2.32-2.39 for Q4, 2.40-2.55 for CST).
// Pure functions: coordinates and section in, element matrices out. SI units.
// DOF order inside an element: (ux1, uy1, ux2, uy2, ...), nodes counterclockwise.
#pragma once
#include <Eigen/Dense>

namespace bb::fe {

struct PlaneSection {
  double youngs_modulus = 0.0;  // E [Pa]
  double poisson_ratio = 0.0;   // nu [-]
  double density = 0.0;         // rho [kg/m^3]
  double thickness = 0.0;       // t [m]
};

using Q4Coords = Eigen::Matrix<double, 4, 2>;
using CstCoords = Eigen::Matrix<double, 3, 2>;
using Matrix8 = Eigen::Matrix<double, 8, 8>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// Thesis eq 2.32.
Eigen::Matrix3d plane_stress_elasticity(double youngs_modulus, double poisson_ratio);

// Isoparametric bilinear quadrilateral, 2x2 Gauss: exact for parallelograms (the thesis's
// rectangles), and the standard choice for distorted shapes. Throws std::domain_error when the
// Jacobian is not positive at a Gauss point (inverted or degenerate element).
Matrix8 q4_stiffness(const Q4Coords& xy, const PlaneSection& section);
Matrix8 q4_consistent_mass(const Q4Coords& xy, const PlaneSection& section);

// Constant-strain triangle. Throws std::domain_error when the signed area is not positive.
Matrix6 cst_stiffness(const CstCoords& xy, const PlaneSection& section);
Matrix6 cst_consistent_mass(const CstCoords& xy, const PlaneSection& section);

// Stress (sxx, syy, sxy) at the element centroid from element nodal displacements.
Eigen::Vector3d q4_centroid_stress(const Q4Coords& xy, const Eigen::Matrix<double, 8, 1>& u,
                                   const PlaneSection& section);
Eigen::Vector3d cst_stress(const CstCoords& xy, const Eigen::Matrix<double, 6, 1>& u, const PlaneSection& section);

}  // namespace bb::fe
