// What a rotating analysis computes (thesis chapter 2): the body of the case's mesh clamped at its
// root to a rotor turning about a fixed axis, in the floating frame of reference (ffrf/): the time
// histories of chosen node sets in the rotating frame, the steady centrifugal deflection, the modes
// linearized about the rotating state and their Campbell diagram with engine-order crossings.
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "common/source_location.hpp"

namespace bb {

// The most steps one rotating run may take (each is kept in the history): given or automatic step.
inline constexpr double kMaxRotatingSteps = 5e7;

struct RotatingSpec {
  // The rotor's motion: a constant speed from t = 0 (the thesis: 300 rad/s), the smooth spin-up of
  // Kane, Ryan & Banerjee (1987) to `speed` over `spin_up_time`, or free under a constant torque.
  enum class Profile { constant, spin_up, torque } profile = Profile::constant;
  double speed = 0.0;          // Omega, or the final speed of a spin-up [rad/s]
  double spin_up_time = 0.0;   // Ts [s]
  double torque = 0.0;         // [N m], profile torque
  double initial_speed = 0.0;  // [rad/s], profile torque
  double rotor_inertia = 0.0;  // J of the rigid rotor about the axis [kg m^2]
  Eigen::Vector3d axis_direction = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();  // [m]
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();     // inertial frame at theta = 0 [m/s^2]

  double end_time = 0.0;      // [s]
  double time_step = 0.0;     // [s]; 0 = 40 steps per period of the lowest rotating mode at `speed`
  double rho_infinity = 0.9;  // generalized-alpha dissipation (ffrf/ffrf_integrator.hpp)
  bool stiffening = true;     // centrifugal pre-stress (geometric) stiffness
  bool coriolis = true;
  bool modal_basis = true;  // elastic coordinates: fixed-interface modes + static shapes, or every free DOF
  int basis_modes = 12;     // modal basis size (modes at rest)

  // Also run the model with the stiffening switched the other way and report both (the linear
  // floating frame without stiffening softens and diverges beyond the first bending frequency).
  bool compare_stiffening = false;

  std::vector<std::string> histories;  // node sets whose mean displacement is recorded
  double history_interval = 1e-3;      // [s] between rows of histories.csv (the statistics use every step)

  std::vector<double> campbell_speeds;  // [rad/s]; empty: 0 .. speed in 10 steps
  int campbell_modes = 6;
  std::vector<int> engine_orders = {1, 2, 3, 4, 5, 6};
  SourceLocation at;
};

}  // namespace bb
