#include "friction/jenkins.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bb::friction {

void validate(const PointParameters& p) {
  const auto require = [](bool ok, const char* what, double value) {
    if (!ok) throw std::invalid_argument(fmt::format("Jenkins contact: {} (got {})", what, value));
  };
  require(std::isfinite(p.kt) && p.kt > 0.0, "tangential stiffness kt must be finite and > 0", p.kt);
  require(std::isfinite(p.kn) && p.kn >= 0.0, "normal stiffness kn must be finite and >= 0", p.kn);
  require(std::isfinite(p.mu) && p.mu >= 0.0, "friction coefficient mu must be finite and >= 0", p.mu);
  require(std::isfinite(p.n0) && p.n0 >= 0.0, "normal preload N0 must be finite and >= 0", p.n0);
}

const char* state_name(ContactState s) {
  switch (s) {
    case ContactState::stick:
      return "stick";
    case ContactState::slip_positive:
      return "slip+";
    case ContactState::slip_negative:
      return "slip-";
    case ContactState::lift_off:
      return "lift-off";
  }
  return "?";
}

JenkinsStep jenkins_step(const PointParameters& p, double slider, double u, double v) {
  const double normal = std::max(p.n0 + p.kn * v, 0.0);
  if (normal <= 0.0) return {.tangential = 0.0, .normal = 0.0, .slider = u, .state = ContactState::lift_off};
  const double limit = p.mu * normal;
  const double trial = p.kt * (u - slider);
  if (std::abs(trial) < limit)
    return {.tangential = trial, .normal = normal, .slider = slider, .state = ContactState::stick};
  const double t = std::copysign(limit, trial);
  return {.tangential = t,
          .normal = normal,
          .slider = u - t / p.kt,
          .state = trial >= 0.0 ? ContactState::slip_positive : ContactState::slip_negative};
}

JenkinsStep2D jenkins_step_2d(const PointParameters& p, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
                              double v) {
  JenkinsStep2D out;
  for (int i = 0; i < 2; ++i) {
    const JenkinsStep s = jenkins_step(p, slider[i], u[i], v);
    out.tangential[i] = s.tangential;
    out.slider[i] = s.slider;
    out.state[static_cast<size_t>(i)] = s.state;
    out.normal = s.normal;
  }
  return out;
}

}  // namespace bb::friction
