// The harmonic balance with a response held and the force unknown: the response-controlled
// stepped sine that modern rigs run (the shaker's force is adjusted at each frequency until the
// response has the asked amplitude). Unknowns (x, Re F, Im F): the contact-DOF harmonics of
// hbm/condensed_balance.hpp and the complex amplitude F of the first force (a multiple of the
// model's harmonic load, given for 1 N), with
//   R(x, F) = L(omega) x + g(x) - b_static - F b_1(omega) = 0,
//   a_1 = amplitude, b_1 = 0 at the held DOF (its first harmonic is the clock: phase 0),
// the two response rows scaled to newtons by the largest entry of L. Units: SI.
#pragma once
#include <Eigen/Dense>

#include <complex>
#include <optional>

#include "hbm/fixed_frequency.hpp"

namespace bb::hbm {

struct ControlledResponse {
  Eigen::Index dof = 0;    // model DOF whose first harmonic is held
  double amplitude = 0.0;  // its first-harmonic amplitude [m], > 0
};

struct ControlledSolution {
  HbmSolution solution;        // x, omega, iterations, converged, failure (|R| of the extended system), contacts
  std::complex<double> force;  // the first force's complex amplitude [N], the held response at phase 0
};

// (x, F) to start from: a neighbouring frequency's solution.
struct ControlledStart {
  Eigen::VectorXd x;
  std::complex<double> force;
};

// Damped Newton on (x, F) from `initial`, else from the linear limits (stuck, then sliding) with
// the force that gives them the held amplitude. `system` must carry the harmonic load of a 1 N
// first force. Never throws on non-convergence (converged == false with |R|), never returns NaN.
[[nodiscard]] ControlledSolution solve_controlled(const HarmonicBalance& system, double omega,
                                                  const ControlledResponse& control,
                                                  const std::optional<ControlledStart>& initial = std::nullopt);

}  // namespace bb::hbm
