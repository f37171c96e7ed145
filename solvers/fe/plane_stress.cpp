#include "fe/plane_stress.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace bb::fe {
namespace {

constexpr double kGauss = 0.57735026918962576451;  // 1/sqrt(3)

struct Q4Point {
  Eigen::Matrix<double, 3, 8> strain_displacement;  // B
  Eigen::Matrix<double, 1, 4> shape;                // N
  double det_jacobian;
};

Q4Point q4_at(const Q4Coords& xy, double xi, double eta) {
  Eigen::Matrix<double, 1, 4> shape;
  shape << (1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta);
  shape *= 0.25;
  Eigen::Matrix<double, 2, 4> dnat;  // d/dxi, d/deta of eq 2.34
  dnat << -(1 - eta), (1 - eta), (1 + eta), -(1 + eta), -(1 - xi), -(1 + xi), (1 + xi), (1 - xi);
  dnat *= 0.25;
  const Eigen::Matrix2d jac = dnat * xy;
  const double det = jac.determinant();
  if (!(det > 0.0)) {
    throw std::domain_error("Q4 Jacobian determinant " + std::to_string(det) +
                            " <= 0 (element inverted, degenerate or not counterclockwise)");
  }
  const Eigen::Matrix<double, 2, 4> dxy = jac.inverse() * dnat;
  Eigen::Matrix<double, 3, 8> b = Eigen::Matrix<double, 3, 8>::Zero();
  for (int a = 0; a < 4; ++a) {
    b(0, 2 * a) = dxy(0, a);
    b(1, 2 * a + 1) = dxy(1, a);
    b(2, 2 * a) = dxy(1, a);
    b(2, 2 * a + 1) = dxy(0, a);
  }
  return {b, shape, det};
}

// Twice the signed area; the CST's B matrix of eq 2.53.
Eigen::Matrix<double, 3, 6> cst_b(const CstCoords& xy, double& area) {
  const double x1 = xy(0, 0), y1 = xy(0, 1), x2 = xy(1, 0), y2 = xy(1, 1), x3 = xy(2, 0), y3 = xy(2, 1);
  const double det = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1);
  if (!(det > 0.0)) {
    throw std::domain_error("CST signed area " + std::to_string(0.5 * det) +
                            " <= 0 (element inverted, degenerate or not counterclockwise)");
  }
  area = 0.5 * det;
  Eigen::Matrix<double, 3, 6> b;
  b << y2 - y3, 0, y3 - y1, 0, y1 - y2, 0, 0, x3 - x2, 0, x1 - x3, 0, x2 - x1, x3 - x2, y2 - y3, x1 - x3, y3 - y1,
      x2 - x1, y1 - y2;
  return b / det;
}

}  // namespace

Eigen::Matrix3d plane_stress_elasticity(double youngs_modulus, double poisson_ratio) {
  Eigen::Matrix3d d;
  d << 1, poisson_ratio, 0, poisson_ratio, 1, 0, 0, 0, 0.5 * (1 - poisson_ratio);
  return youngs_modulus / (1 - poisson_ratio * poisson_ratio) * d;
}

Matrix8 q4_stiffness(const Q4Coords& xy, const PlaneSection& section) {
  const Eigen::Matrix3d d = plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio);
  Matrix8 k = Matrix8::Zero();
  for (double xi : {-kGauss, kGauss}) {
    for (double eta : {-kGauss, kGauss}) {
      const Q4Point p = q4_at(xy, xi, eta);
      k.noalias() +=
          p.strain_displacement.transpose() * d * p.strain_displacement * (p.det_jacobian * section.thickness);
    }
  }
  return 0.5 * (k + k.transpose());
}

Matrix8 q4_consistent_mass(const Q4Coords& xy, const PlaneSection& section) {
  Eigen::Matrix4d scalar = Eigen::Matrix4d::Zero();
  for (double xi : {-kGauss, kGauss}) {
    for (double eta : {-kGauss, kGauss}) {
      const Q4Point p = q4_at(xy, xi, eta);
      scalar.noalias() += p.shape.transpose() * p.shape * (p.det_jacobian * section.density * section.thickness);
    }
  }
  Matrix8 m = Matrix8::Zero();
  for (int a = 0; a < 4; ++a) {
    for (int c = 0; c < 4; ++c) {
      m(2 * a, 2 * c) = scalar(a, c);
      m(2 * a + 1, 2 * c + 1) = scalar(a, c);
    }
  }
  return m;
}

Matrix6 cst_stiffness(const CstCoords& xy, const PlaneSection& section) {
  double area = 0.0;
  const Eigen::Matrix<double, 3, 6> b = cst_b(xy, area);
  const Eigen::Matrix3d d = plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio);
  const Matrix6 k = b.transpose() * d * b * (area * section.thickness);  // eq 2.54
  return 0.5 * (k + k.transpose());
}

Matrix6 cst_consistent_mass(const CstCoords& xy, const PlaneSection& section) {
  double area = 0.0;
  cst_b(xy, area);
  // Exact integral of eq 2.55: rho t A / 12 * (1 + delta_ab) per direction.
  const double scale = section.density * section.thickness * area / 12.0;
  Matrix6 m = Matrix6::Zero();
  for (int a = 0; a < 3; ++a) {
    for (int c = 0; c < 3; ++c) {
      const double v = scale * (a == c ? 2.0 : 1.0);
      m(2 * a, 2 * c) = v;
      m(2 * a + 1, 2 * c + 1) = v;
    }
  }
  return m;
}

Eigen::Vector3d q4_centroid_stress(const Q4Coords& xy, const Eigen::Matrix<double, 8, 1>& u,
                                   const PlaneSection& section) {
  const Q4Point p = q4_at(xy, 0.0, 0.0);
  return plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio) * p.strain_displacement * u;
}

Eigen::Vector3d cst_stress(const CstCoords& xy, const Eigen::Matrix<double, 6, 1>& u, const PlaneSection& section) {
  double area = 0.0;
  const Eigen::Matrix<double, 3, 6> b = cst_b(xy, area);
  return plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio) * b * u;
}

}  // namespace bb::fe
