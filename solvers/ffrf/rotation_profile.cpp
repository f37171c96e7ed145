#include "ffrf/rotation_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "common/constants.hpp"
#include "common/errors.hpp"

namespace bb::ffrf {
namespace {

void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw InputError(fmt::format("rotation profile: {} must be finite, got {}", what, v));
}

}  // namespace

RotationProfile RotationProfile::constant_speed(double speed, double initial_angle) {
  require_finite(speed, "speed");
  require_finite(initial_angle, "initial angle");
  RotationProfile p;
  p.kind_ = Kind::constant_speed;
  p.omega_ = speed;
  p.theta0_ = initial_angle;
  p.omega0_ = speed;
  return p;
}

RotationProfile RotationProfile::spin_up(double final_speed, double ramp_time) {
  require_finite(final_speed, "final speed");
  if (!(ramp_time > 0.0) || !std::isfinite(ramp_time))
    throw InputError(fmt::format("spin-up profile: ramp time Ts must be > 0, got {}", ramp_time));
  RotationProfile p;
  p.kind_ = Kind::spin_up;
  p.omega_ = final_speed;
  p.ramp_ = ramp_time;
  return p;
}

RotationProfile RotationProfile::free(std::function<double(double)> torque, double initial_speed, double initial_angle,
                                      std::string description) {
  if (!torque) throw InputError("free rotation profile: a torque history is required (use [](double) { return 0; })");
  require_finite(initial_speed, "initial speed");
  require_finite(initial_angle, "initial angle");
  RotationProfile p;
  p.kind_ = Kind::free;
  p.torque_ = std::move(torque);
  p.omega0_ = initial_speed;
  p.theta0_ = initial_angle;
  p.description_ = std::move(description);
  return p;
}

double RotationProfile::angle(double t) const {
  switch (kind_) {
    case Kind::constant_speed:
      return theta0_ + omega_ * t;
    case Kind::spin_up: {
      if (t >= ramp_) return omega_ * t - 0.5 * omega_ * ramp_;
      const double c = ramp_ / kTwoPi;
      return omega_ / ramp_ * (0.5 * t * t + c * c * (std::cos(kTwoPi * t / ramp_) - 1.0));
    }
    case Kind::free:
      break;
  }
  throw std::logic_error("RotationProfile::angle: the rotor is free, theta is an unknown");
}

double RotationProfile::speed(double t) const {
  switch (kind_) {
    case Kind::constant_speed:
      return omega_;
    case Kind::spin_up:
      if (t >= ramp_) return omega_;
      return omega_ / ramp_ * (t - ramp_ / kTwoPi * std::sin(kTwoPi * t / ramp_));
    case Kind::free:
      break;
  }
  throw std::logic_error("RotationProfile::speed: the rotor is free, Omega is an unknown");
}

double RotationProfile::acceleration(double t) const {
  switch (kind_) {
    case Kind::constant_speed:
      return 0.0;
    case Kind::spin_up:
      if (t >= ramp_) return 0.0;
      return omega_ / ramp_ * (1.0 - std::cos(kTwoPi * t / ramp_));
    case Kind::free:
      break;
  }
  throw std::logic_error("RotationProfile::acceleration: the rotor is free, alpha is an unknown");
}

double RotationProfile::max_speed(double t_end) const {
  if (kind_ == Kind::free) throw std::logic_error("RotationProfile::max_speed: the rotor is free");
  // Both prescribed profiles are monotone in |Omega|.
  return std::max(std::abs(speed(0.0)), std::abs(speed(t_end)));
}

double RotationProfile::torque(double t) const {
  if (kind_ != Kind::free) throw std::logic_error("RotationProfile::torque: the rotation is prescribed");
  return torque_(t);
}

std::string RotationProfile::describe() const {
  switch (kind_) {
    case Kind::constant_speed:
      return fmt::format("constant speed {} rad/s", omega_);
    case Kind::spin_up:
      return fmt::format("spin-up to {} rad/s in {} s", omega_, ramp_);
    case Kind::free:
      return fmt::format("free rotor ({}), Omega0 = {} rad/s", description_, omega0_);
  }
  return "?";
}

}  // namespace bb::ffrf
