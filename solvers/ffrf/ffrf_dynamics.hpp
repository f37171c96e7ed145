// Internal to ffrf/: the operators of the floating-frame equations of one run (a ProjectedBody
// with the run's switches: stiffening, Coriolis, damping, gravity, rotor inertia), and the
// energy-like quantities of a state. Shared by the integrator's prescribed and free-rotor steppers
// and by the rotating modal solver. Formulas: ffrf/ffrf_integrator.hpp. SI units.
#pragma once
#include <Eigen/Dense>

#include <functional>

#include "ffrf/elastic_basis.hpp"

namespace bb::ffrf::detail {

struct Switches {
  bool stiffening = true;
  bool coriolis = true;
  double rayleigh_mass = 0.0;
  double rayleigh_stiffness = 0.0;
  double rotor_inertia = 0.0;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::function<Eigen::VectorXd(double)> external_load;  // free DOFs [N]
};

// Energy, momentum and gravity quantities of a state (theta, Omega, q, q').
struct Snapshot {
  double kinetic = 0.0;            // T [J]
  double strain = 0.0;             // U [J]
  double momentum = 0.0;           // H [kg m^2/s]
  double gravity_potential = 0.0;  // V_g = -g . R(theta) (s0 + F_g^T q) [J]
  double gravity_moment = 0.0;     // Q_g = -dV_g/dtheta [N m]
  double rms_deflection = 0.0;     // sqrt(q^T M q / m) [m]
};

class Dynamics {
 public:
  Dynamics(const ProjectedBody& body, const Switches& switches);

  const ProjectedBody& body() const { return p_; }
  double stiffening() const { return s_; }
  double coriolis() const { return cor_; }
  bool damped() const { return damped_; }
  bool loaded() const { return static_cast<bool>(external_); }
  const Switches& switches() const { return sw_; }

  const CoordinateMatrix& softening() const { return softening_; }  // M_p - s K_s1
  const CoordinateMatrix& damping() const { return damping_; }      // C (zero matrix when undamped)
  const Eigen::VectorXd& coupling0() const { return g0_; }          // g0 = G (x - p)

  Eigen::VectorXd h(const Eigen::VectorXd& q) const;                                        // f_c + (M_p - s K_s1) q
  Eigen::VectorXd coupling(const Eigen::VectorXd& q) const;                                 // g0 + G q
  double axis_inertia(const Eigen::VectorXd& q, const Eigen::VectorXd& hq) const;           // J(q)
  Eigen::VectorXd gravity_load(double theta) const;                                         // F_g R(theta)^T g
  Eigen::VectorXd gravity_load_derivative(double theta) const;                              // d/dtheta of the above
  double gravity_moment(double theta, const Eigen::VectorXd& q, int derivative = 0) const;  // Q_g, dQ_g/dtheta
  Eigen::VectorXd gravity_moment_gradient(double theta) const;                              // dQ_g/dq
  Eigen::VectorXd external_load(double t) const;                                            // in basis coordinates
  Eigen::VectorXd damping_force(const Eigen::VectorXd& v) const;                            // C v

  Snapshot snapshot(double theta, double omega, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  double momentum(double omega, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;  // H

  // Static operator and load at a speed (steady state in the rotating frame):
  // (K + s Omega^2 K_s1 - Omega^2 M_p + alpha G) q = Omega^2 f_c + alpha f_alpha + F_g R^T g.
  CoordinateMatrix static_operator(double omega, double alpha) const;
  Eigen::VectorXd static_load(double theta, double omega, double alpha) const;

 private:
  const ProjectedBody& p_;
  Switches sw_;
  double s_ = 1.0, cor_ = 1.0;
  bool damped_ = false;
  CoordinateMatrix softening_, damping_;
  Eigen::VectorXd g0_;
  Eigen::VectorXd gravity_;  // dim entries
  std::function<Eigen::VectorXd(double)> external_;
};

}  // namespace bb::ffrf::detail
