// The rotor's motion: prescribed (theta, Omega = theta', alpha = theta'' as functions of time) or
// free under an applied torque history (theta is then an unknown of the coupled equations).
// Units: rad, rad/s, rad/s^2, N m, s.
#pragma once
#include <functional>
#include <string>

namespace bb::ffrf {

class RotationProfile {
 public:
  enum class Kind { constant_speed, spin_up, free };

  // theta = theta0 + Omega t (from t = 0; the body starts at speed at t = 0).
  static RotationProfile constant_speed(double speed, double initial_angle = 0.0);
  // Kane, Ryan & Banerjee (1987), Simo & Vu-Quoc (1987) spin-up: for t <= Ts,
  //   theta = (Os / Ts) [t^2 / 2 + (Ts / 2 pi)^2 (cos(2 pi t / Ts) - 1)],
  // theta = Os t - Os Ts / 2 after; Omega and alpha are continuous, alpha(0) = alpha(Ts) = 0.
  static RotationProfile spin_up(double final_speed, double ramp_time);
  // Free rotation: the rotor is driven by torque(t) [N m] about the axis; theta0 and Omega0 at t = 0.
  static RotationProfile free(std::function<double(double)> torque, double initial_speed = 0.0,
                              double initial_angle = 0.0, std::string description = "applied torque");

  Kind kind() const { return kind_; }
  bool prescribed() const { return kind_ != Kind::free; }

  // Prescribed profiles only (std::logic_error for a free rotor).
  double angle(double t) const;
  double speed(double t) const;
  double acceleration(double t) const;
  // Largest |Omega| the profile reaches on [0, t_end] (prescribed), for scales and bounds.
  double max_speed(double t_end) const;

  // Free rotor: the applied torque, and the initial state.
  double torque(double t) const;
  double initial_angle() const { return theta0_; }
  double initial_speed() const { return omega0_; }

  std::string describe() const;

 private:
  Kind kind_ = Kind::constant_speed;
  double omega_ = 0.0;  // constant speed, or the final speed Os of a spin-up
  double ramp_ = 0.0;   // Ts
  double theta0_ = 0.0;
  double omega0_ = 0.0;
  std::function<double(double)> torque_;
  std::string description_;
};

}  // namespace bb::ffrf
