// Damper geometries shared by the damper unit tests. Units: SI.
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <numbers>

#include "damper/rigid_damper.hpp"

namespace bb::damper::test {

inline double rad(double deg) { return deg * std::numbers::pi / 180.0; }
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Symmetric damper: face angles beta on both sides, the right point R = (a, b) and the left face
// centre (-a, b), mirror images about x = 0; L1 and L2 at -s and +s along the left face from its
// centre. m = 0.05 kg, J = 2e-6 kg m^2 (a small steel wedge).
inline AsymmetricDamperGeometry symmetric_geometry(double beta_deg, double a = 4e-3, double b = 2e-3,
                                                   double s = 1.5e-3) {
  const Eigen::Vector2d c(-a, b), t(std::cos(rad(beta_deg)), std::sin(rad(beta_deg)));
  AsymmetricDamperGeometry g;
  g.mass = 0.05;
  g.inertia = 2e-6;
  g.beta_left_deg = beta_deg;
  g.beta_right_deg = beta_deg;
  g.l1 = c - s * t;
  g.l2 = c + s * t;
  g.r = Eigen::Vector2d(a, b);
  return g;
}

// Asymmetric damper: beta_L = 40, beta_R = 55 degrees, points chosen so that every contact carries
// load under CF along +y (checked by the tests, not assumed).
inline AsymmetricDamperGeometry asymmetric_geometry() {
  const Eigen::Vector2d c(-4e-3, 1.5e-3), t(std::cos(rad(40.0)), std::sin(rad(40.0)));
  AsymmetricDamperGeometry g;
  g.mass = 0.04;
  g.inertia = 1.5e-6;
  g.beta_left_deg = 40.0;
  g.beta_right_deg = 55.0;
  g.l1 = c + 0.5e-3 * t;
  g.l2 = c + 3.5e-3 * t;
  g.r = Eigen::Vector2d(3.5e-3, 2.5e-3);
  return g;
}

// Independent statics of a frictionless rigid damper with three contacts: the normal loads that
// balance a force CF along +y at G, from the three equations written out by hand.
inline Eigen::Vector3d three_point_statics(const RigidDamper& d, double cf) {
  Eigen::Matrix3d e;
  for (int c = 0; c < 3; ++c) {
    const DamperContact& p = d.contacts[static_cast<size_t>(c)];
    e(0, c) = p.normal.x();
    e(1, c) = p.normal.y();
    e(2, c) = cross2(p.position, p.normal);
  }
  return e.fullPivLu().solve(Eigen::Vector3d(0.0, -cf, 0.0));
}

}  // namespace bb::damper::test
