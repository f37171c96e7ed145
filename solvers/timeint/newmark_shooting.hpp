// The periodic response by shooting on the period map of the Newmark / HHT-alpha integrator
// (timeint/newmark.hpp): Newton on x(T) - x(0) = 0 with x = (q, dq/dtheta, d2q/dtheta2, sliders),
// the monodromy carried step by step through the consistent tangent of each implicit step, and its
// eigenvalues (Floquet multipliers of the discrete map) for stability. Units: SI.
//
// Where the exact flow (timeint/shooting.hpp) follows every transition and every ringing mode, this
// map has a fixed cost per period whatever the model's fastest modes: a reduced blade whose modes
// reach thousands of times the excitation frequency, which the exact flow cuts into thousands of
// pieces per period. The answer carries Newmark's time-step error (second order while contacts do
// not change state inside a step; transitions are taken by return mapping, not located), and
// HHT's alpha < 0 damps the modes the step does not resolve.
#pragma once
#include <Eigen/Dense>

#include <optional>

#include "friction/friction_system.hpp"
#include "timeint/period_newton.hpp"
#include "timeint/shooting.hpp"

namespace bb::timeint {

struct NewmarkShootingResult {
  // steps_per_period = Newmark steps; samples and largest from the steps (extremes not located);
  // start is left empty (the state below starts the next frequency).
  ShootingResult result;
  Eigen::VectorXd state;  // the periodic x at theta = 0
};

// `alpha`: HHT alpha in [-1/3, 0]. Throws std::invalid_argument on invalid options; a run that does
// not converge says so in result.steady.failure with |R| and the iteration count.
[[nodiscard]] NewmarkShootingResult newmark_shooting(const friction::FrictionModel& model, double omega_rad_s,
                                                     const ShootingOptions& options, double alpha,
                                                     const std::optional<Eigen::VectorXd>& start = std::nullopt);

// The period map itself, over x = (q, v / omega, a / omega^2, sliders) (every entry in metres), its
// monodromy in the same variables: for tests and for callers that march it themselves.
[[nodiscard]] PeriodMap newmark_period_map(const friction::FrictionModel& model, double omega_rad_s,
                                           int steps_per_period, double alpha);

// The map's state x as a Newmark state at t = 0 (the sliders settled onto their modes), and back:
// a march (timeint/steady_state.hpp) continues from the one, Newton starts from the other.
[[nodiscard]] DynamicState newmark_state(const friction::FrictionModel& model, double omega_rad_s,
                                         const Eigen::VectorXd& x);
[[nodiscard]] Eigen::VectorXd newmark_packed(const DynamicState& state, double omega_rad_s);

}  // namespace bb::timeint
