// The periodic response by shooting: Newton's method on the period map of the exact piecewise-linear
// flow (timeint/piecewise_flow.hpp), x(2 pi) - x(0) = 0 for x = (q, dq/dtheta, sliders), with the
// monodromy matrix as its Jacobian, and its eigenvalues (Floquet multipliers) for stability. No
// harmonic truncation and no time-step error: the answer is exact to the Newton tolerance and the
// location of the transitions. Units: SI.
//
// A contact stuck over the whole period leaves its slider free (any position repeats): its residual
// row is replaced by "slider unchanged" and its multiplier (exactly 1) is left out of the stability
// verdict, which compares the largest remaining modulus with 1.
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

#include "friction/friction_system.hpp"
#include "timeint/period_newton.hpp"
#include "timeint/piecewise_flow.hpp"
#include "timeint/steady_state.hpp"

namespace bb::timeint {

struct ShootingOptions {
  std::vector<Eigen::Index> dofs;  // DOFs reported (harmonics 0..H and largest |q|), at least one
  int steps_per_period = 128;      // sub-intervals that bracket the transitions; >= 2 (harmonics + 1)
  int harmonics = 1;
  // Converged when max |x(2 pi) - x(0)|, or a Newton correction of q and dq/dtheta (at the rounding
  // floor), is at most tolerance * max(|q|, |dq/dtheta|) at the start [m].
  double tolerance = 1e-9;
  int max_iterations = 40;  // Newton iterations
  int warmup_periods = 20;  // without a start: periods marched from the static state first
  int max_events = 100000;  // transitions in one period before the flow is declared chattering
  bool floquet = false;     // multipliers and the stability verdict
  // The exact flow only: Coulomb's stick (timeint/piecewise_flow.hpp, a stuck contact held rigidly,
  // kt unused) instead of the Jenkins spring.
  bool rigid_stick = false;
  StaticOptions initial{};  // the static state a run without a start begins from
};

struct ShootingResult {
  // coefficients, amplitude, phase (the Fourier integrals of the exact motion, not a DFT of the
  // samples), contacts (steps_per_period + 1 samples), converged, failure; cycles = periods
  // integrated, total_iterations = Newton iterations.
  SteadyState steady;
  Eigen::MatrixXd samples;          // (steps_per_period + 1) x reported DOFs: q at the sub-interval ends [m]
  Eigen::VectorXd largest;          // per reported DOF, max |q_d| over the period (extremes located) [m]
  double residual = 0.0;            // max |x(2 pi) - x(0)| at the answer [m]
  int transitions = 0;              // contact transitions over the period
  Eigen::VectorXcd multipliers;     // with floquet: by decreasing modulus, free sliders left out
  double largest_multiplier = 0.0;  // |multiplier| max; NaN without floquet
  bool stable = false;              // largest_multiplier < 1 (with floquet)
  FlowState start;                  // the periodic state at theta = 0 (a start for the next frequency)
};

// Throws std::invalid_argument unless omega > 0 and finite and the options are valid (DOFs of the
// model, steps_per_period >= 2 (harmonics + 1), tolerance > 0, ...): what both period maps require.
void validate_shooting(const friction::FrictionModel& model, double omega_rad_s, const ShootingOptions& options);

// Throws std::invalid_argument unless the contacts' tangential rows are independent, as Coulomb's
// stick needs (each stuck contact holds its own u).
void validate_rigid_stick(const friction::FrictionModel& model);

// The start of a run given none, x of `size` entries: the static state (q first, the sliders from
// slider_offset, the rest zero), then periods of `map` marched until one changes q and its rate
// (the first 2 n entries) by at most 1e-3 of their largest, at most options.warmup_periods. A
// failed period leaves the state before it, with the reason in `failure`.
Eigen::VectorXd warm_start(const friction::FrictionModel& model, const PeriodMap& map, Eigen::Index size,
                           Eigen::Index slider_offset, const ShootingOptions& options, int& periods,
                           std::string& failure);

// A Newton run on a period map into `out` (either map's): the periods, iterations and |R|; the
// failure, or converged with the transitions and, with `floquet`, the multipliers and the verdict.
// False when it did not converge.
bool take_newton(const PeriodNewtonResult& newton, const PeriodLayout& layout, bool floquet, ShootingResult& out);

// Throws std::invalid_argument on invalid options; a run that does not converge says so in
// steady.failure with |R| and the iteration count (converged == false).
[[nodiscard]] ShootingResult shooting(const friction::FrictionModel& model, double omega_rad_s,
                                      const ShootingOptions& options,
                                      const std::optional<FlowState>& start = std::nullopt);

}  // namespace bb::timeint
