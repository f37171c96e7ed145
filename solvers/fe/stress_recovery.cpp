// Extrapolation matrices and stress invariants (see the header). SI units.
#include "fe/stress_recovery.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "fe/gauss_abscissae.hpp"

namespace bb::fe {
namespace {

// The 2-point rule's abscissa is 1/sqrt(3): a node at +-1 lies at +-sqrt(3) in units of it.
constexpr double kSqrt3 = 1.7320508075688772935;

// Linear Lagrange basis through r = -1, +1 evaluated at r.
double linear(int i, double r) { return 0.5 * (1.0 + (i == 0 ? -r : r)); }

// Quadratic Lagrange basis through -g, 0, +g evaluated at t.
double quadratic(int i, double t) {
  const double g2 = kG3 * kG3;
  switch (i) {
    case 0:
      return t * (t - kG3) / (2 * g2);
    case 1:
      return (g2 - t * t) / g2;
    default:
      return t * (t + kG3) / (2 * g2);
  }
}

// Natural coordinates of the nodes (mesh/mesh.hpp order): corners, then hex20's mid-edge nodes.
constexpr double kHexNodes[20][3] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
    {-1, 1, 1},   {0, -1, -1}, {1, 0, -1},  {0, 1, -1},  {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},
    {0, 1, 1},    {-1, 0, 1},  {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},   {-1, 1, 0},
};
constexpr double kQuadNodes[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

}  // namespace

const Eigen::Matrix<double, 4, 4>& q4_extrapolation() {
  static const Eigen::Matrix<double, 4, 4> e = [] {
    Eigen::Matrix<double, 4, 4> m;
    for (int a = 0; a < 4; ++a)
      for (int j = 0, p = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i, ++p)
          m(a, p) = linear(i, kSqrt3 * kQuadNodes[a][0]) * linear(j, kSqrt3 * kQuadNodes[a][1]);
    return m;
  }();
  return e;
}

const Eigen::Matrix<double, 3, 1>& cst_extrapolation() {
  static const Eigen::Matrix<double, 3, 1> e = Eigen::Vector3d::Ones();
  return e;
}

const Eigen::Matrix<double, 8, 8>& hex8_extrapolation() {
  static const Eigen::Matrix<double, 8, 8> e = [] {
    Eigen::Matrix<double, 8, 8> m;
    for (int a = 0; a < 8; ++a)
      for (int k = 0, p = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i, ++p)
            m(a, p) = linear(i, kSqrt3 * kHexNodes[a][0]) * linear(j, kSqrt3 * kHexNodes[a][1]) *
                      linear(k, kSqrt3 * kHexNodes[a][2]);
    return m;
  }();
  return e;
}

const Eigen::Matrix<double, 20, 27>& hex20_extrapolation() {
  static const Eigen::Matrix<double, 20, 27> e = [] {
    Eigen::Matrix<double, 20, 27> m;
    for (int a = 0; a < 20; ++a)
      for (int k = 0, p = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i, ++p)
            m(a, p) = quadratic(i, kHexNodes[a][0]) * quadratic(j, kHexNodes[a][1]) * quadratic(k, kHexNodes[a][2]);
    return m;
  }();
  return e;
}

double von_mises_plane(const Eigen::Vector3d& s) {
  return std::sqrt(std::max(0.0, s[0] * s[0] - s[0] * s[1] + s[1] * s[1] + 3 * s[2] * s[2]));
}

Eigen::Vector2d principal_plane(const Eigen::Vector3d& s) {
  const double centre = 0.5 * (s[0] + s[1]);
  const double radius = std::hypot(0.5 * (s[0] - s[1]), s[2]);
  return {centre + radius, centre - radius};
}

double von_mises_solid(const Vector6& s) {
  const double d01 = s[0] - s[1], d12 = s[1] - s[2], d20 = s[2] - s[0];
  return std::sqrt(
      std::max(0.0, 0.5 * (d01 * d01 + d12 * d12 + d20 * d20) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
}

Eigen::Vector3d principal_solid(const Vector6& s) {
  Eigen::Matrix3d t;
  t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  // Eigenvalues only, ascending; the iterative solver stays accurate for close principal values.
  const Eigen::Vector3d ascending =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(t, Eigen::EigenvaluesOnly).eigenvalues();
  return ascending.reverse();
}

Eigen::Vector4d plane_stress_strains(const Eigen::Vector3d& s, double youngs_modulus, double poisson_ratio) {
  const double e = youngs_modulus, nu = poisson_ratio;
  return {(s[0] - nu * s[1]) / e, (s[1] - nu * s[0]) / e, 2 * (1 + nu) * s[2] / e, -nu * (s[0] + s[1]) / e};
}

Vector6 solid_strains(const Vector6& s, double youngs_modulus, double poisson_ratio) {
  const double e = youngs_modulus, nu = poisson_ratio;
  Vector6 eps;
  eps << (s[0] - nu * (s[1] + s[2])) / e, (s[1] - nu * (s[2] + s[0])) / e, (s[2] - nu * (s[0] + s[1])) / e,
      2 * (1 + nu) * s[3] / e, 2 * (1 + nu) * s[4] / e, 2 * (1 + nu) * s[5] / e;
  return eps;
}

}  // namespace bb::fe
