#include "ffrf/ffrf_dynamics.hpp"

#include <algorithm>
#include <cmath>

namespace bb::ffrf::detail {

Dynamics::Dynamics(const ProjectedBody& body, const Switches& switches)
    : p_(body), sw_(switches), s_(switches.stiffening ? 1.0 : 0.0), cor_(switches.coriolis ? 1.0 : 0.0) {
  softening_ = combine({{1.0, &p_.projected_mass}, {-s_, &p_.geometric_stiffness}});
  damped_ = switches.rayleigh_mass != 0.0 || switches.rayleigh_stiffness != 0.0;
  damping_ = combine({{switches.rayleigh_mass, &p_.mass}, {switches.rayleigh_stiffness, &p_.stiffness}});
  g0_ = -p_.euler_load;
  gravity_ = switches.gravity.head(p_.dim);
  if (switches.external_load) {
    const ElasticBasis* basis = p_.basis;
    auto load = switches.external_load;
    external_ = [basis, load](double t) { return load_in_basis(*basis, load(t)); };
  }
}

Eigen::VectorXd Dynamics::h(const Eigen::VectorXd& q) const { return p_.centrifugal_load + softening_ * q; }

Eigen::VectorXd Dynamics::coupling(const Eigen::VectorXd& q) const { return g0_ + p_.gyroscopic * q; }

double Dynamics::axis_inertia(const Eigen::VectorXd& q, const Eigen::VectorXd& hq) const {
  // J(q) = J_rotor + J0 + 2 q^T f_c + q^T (M_p - s K_s1) q = J_rotor + J0 + q^T (f_c + h(q)).
  return sw_.rotor_inertia + p_.mass_properties.axis_inertia + q.dot(p_.centrifugal_load + hq);
}

Eigen::VectorXd Dynamics::gravity_load(double theta) const {
  return p_.gravity_load * (axis_rotation(*p_.body, theta).transpose() * gravity_);
}

Eigen::VectorXd Dynamics::gravity_load_derivative(double theta) const {
  return p_.gravity_load * (axis_rotation_derivative(*p_.body, theta, 1).transpose() * gravity_);
}

// V_g = -g . R(theta) w(q), w = s0 + F_g^T q (first moment of the deformed body about the axis
// point, body frame); Q_g = -dV_g/dtheta = g . R'(theta) w: the moment of gravity about the axis.
double Dynamics::gravity_moment(double theta, const Eigen::VectorXd& q, int derivative) const {
  const Eigen::VectorXd w = p_.mass_properties.first_moment + p_.gravity_load.transpose() * q;
  return gravity_.dot(axis_rotation_derivative(*p_.body, theta, derivative + 1) * w);
}

// dQ_g/dq = F_g R'(theta)^T g = d(F_g R^T g)/dtheta: the coupled Jacobian is symmetric in gravity.
Eigen::VectorXd Dynamics::gravity_moment_gradient(double theta) const { return gravity_load_derivative(theta); }

Eigen::VectorXd Dynamics::external_load(double t) const {
  return external_ ? external_(t) : Eigen::VectorXd::Zero(p_.n());
}

Eigen::VectorXd Dynamics::damping_force(const Eigen::VectorXd& v) const {
  return damped_ ? damping_ * v : Eigen::VectorXd::Zero(v.size());
}

Snapshot Dynamics::snapshot(double theta, double omega, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  Snapshot s;
  const Eigen::VectorXd hq = h(q);
  const Eigen::VectorXd c = coupling(q);
  const double j = axis_inertia(q, hq);
  s.kinetic = 0.5 * p_.mass.form(v, v) + omega * v.dot(c) + 0.5 * omega * omega * j;
  s.strain = 0.5 * p_.stiffness.form(q, q);
  s.momentum = omega * j + v.dot(c);
  const Eigen::VectorXd w = p_.mass_properties.first_moment + p_.gravity_load.transpose() * q;
  s.gravity_potential = -gravity_.dot(axis_rotation(*p_.body, theta) * w);
  s.gravity_moment = gravity_.dot(axis_rotation_derivative(*p_.body, theta, 1) * w);
  s.rms_deflection = std::sqrt(std::max(p_.mass.form(q, q), 0.0) / p_.mass_properties.mass);
  return s;
}

double Dynamics::momentum(double omega, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  return omega * axis_inertia(q, h(q)) + v.dot(coupling(q));
}

CoordinateMatrix Dynamics::static_operator(double omega, double alpha) const {
  return combine({{1.0, &p_.stiffness}, {-omega * omega, &softening_}, {alpha, &p_.gyroscopic}});
}

Eigen::VectorXd Dynamics::static_load(double theta, double omega, double alpha) const {
  Eigen::VectorXd f = omega * omega * p_.centrifugal_load + alpha * p_.euler_load;
  if (!gravity_.isZero()) f += gravity_load(theta);
  return f;
}

}  // namespace bb::ffrf::detail
