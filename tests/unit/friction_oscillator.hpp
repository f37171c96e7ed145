// The one-DOF friction oscillator m x'' + c x' + k x + T(x) = F cos(omega t), T a Jenkins contact
// between the mass and the ground at constant normal load N0 (a_n = 0, so kn plays no part; a
// stuck contact is the spring kt from x = 0), as a friction system of hbm/friction_system.hpp: the
// smallest complete use of the harmonic balance and the AFT. Units: SI.
#pragma once
#include <Eigen/Dense>

#include <cmath>

#include "friction/jenkins.hpp"
#include "hbm/harmonic_balance.hpp"

namespace bb::test {

struct FrictionOscillator {
  double mass = 0.0;                  // m [kg]
  double damping = 0.0;               // c [N s/m]
  double stiffness = 0.0;             // k [N/m]
  double force = 0.0;                 // F [N], amplitude of the cosine excitation
  friction::PointParameters contact;  // to the ground, u = x

  friction::FrictionModel model() const {
    friction::FrictionModel m;
    m.mass = Eigen::MatrixXd::Constant(1, 1, mass);
    m.damping = Eigen::MatrixXd::Constant(1, 1, damping);
    m.stiffness = Eigen::MatrixXd::Constant(1, 1, stiffness);
    m.contacts.push_back(
        {.point = contact, .tangential = Eigen::RowVectorXd::Ones(1), .normal = Eigen::RowVectorXd::Zero(1)});
    m.harmonic_load = Eigen::VectorXcd::Constant(1, force);
    return m;
  }
};

// sqrt(a1^2 + b1^2) of the single DOF [m] (one contact DOF: x is its coefficients, layout of friction/aft.hpp).
inline double first_harmonic_amplitude(const hbm::HbmSolution& s) {
  return s.x.size() >= 3 ? std::hypot(s.x[1], s.x[2]) : 0.0;
}

}  // namespace bb::test
