// Stepped-sine steady state by direct time integration (thesis section 3.4.1, eqs 3.40-3.42): the
// model of hbm/friction_system.hpp driven by f_static + Re(F e^{i omega t}) is integrated with
// timeint/newmark.hpp, a fixed number of steps per period (dt = k / f of eq 3.42), period after period
// until the motion repeats, then the harmonics 0..H of chosen DOFs come from a DFT over the last
// whole periods. Units: SI.
//
// Where the thesis runs a fixed number of cycles n (eq 3.41) and so cannot tell a transient from
// the steady state, the run here stops on a measured criterion (cycle-to-cycle change) and says
// whether it met it; the final state is returned so the next frequency of a sweep starts from it
// (the transient between neighbouring frequencies is short, the one from rest is not).
#pragma once
#include <Eigen/Dense>

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "friction/friction_system.hpp"
#include "timeint/newmark.hpp"
#include "timeint/static_state.hpp"

namespace bb::timeint {

struct SteadyStateOptions {
  std::vector<Eigen::Index> dofs;  // DOFs tracked for convergence and analysed (at least one)
  int steps_per_period = 256;      // dt = 2 pi / (omega steps_per_period); >= 2 (harmonics + 1)
  int harmonics = 1;               // H >= 0: harmonics 0..H extracted
  // Converged when, over one whole period, max_k |x_j(theta_k) - x_j-1(theta_k)| <= tolerance *
  // max_k |x_j(theta_k)| for every tracked DOF x (j the period, theta_k its samples): the largest
  // sample-by-sample change between consecutive periods, relative to the DOF's largest value.
  double tolerance = 1e-6;
  // A DOF held only by friction (a damper with no spring of its own) can walk: its mean moves by
  // the same amount every period while the oscillation is periodic (ratcheting; the harmonic
  // balance, periodic by construction, cannot show it). With ignore_drift the convergence test
  // compares each period's samples with their period mean removed and the DFT removes the linear
  // trend; the drift per period is reported either way.
  bool ignore_drift = false;
  int min_cycles = 2;        // periods always integrated
  int max_cycles = 2000;     // cap; reaching it gives converged == false with the last change
  int periods_analysed = 1;  // whole periods at the end that enter the DFT (<= min_cycles)
  // Where the cap is reached, the motion is tested for a period of k forcing periods, k = 2 up to
  // this (a subharmonic response), and the first-harmonic amplitude of each period is kept over the
  // last envelope_periods periods (its range: the envelope of a motion that does not repeat).
  int max_period_multiple = 8;
  int envelope_periods = 100;
  // Newmark options; time_step is set from omega and steps_per_period.
  NewmarkOptions newmark{};
  // The static initial state used when no start state is given (a damper held only by friction
  // needs StaticFriction::stuck_at_offset).
  StaticOptions initial{};
};

struct SteadyState {
  double omega = 0.0;  // [rad/s]
  // Rows follow options.dofs. Real layout of friction/aft.hpp: [c0, a1, b1, ..., aH, bH] with
  // x(t) = c0 + sum a_h cos(h omega t) + b_h sin(h omega t).
  Eigen::MatrixXd coefficients;
  Eigen::MatrixXd amplitude;  // [|c0|, sqrt(a_h^2 + b_h^2)...], H + 1 columns [m]
  Eigen::MatrixXd phase;      // arg(a_h - i b_h): x_h = A_h cos(h omega t + phase_h) [rad]; 0 for h = 0
  int cycles = 0;             // periods integrated
  double change = 0.0;        // last cycle-to-cycle change (relative, as tested)
  Eigen::VectorXd drift;      // per tracked DOF, change of the period mean over the last period [m]
  bool converged = false;
  // 1 when converged; k >= 2 when the cap was reached but the motion repeats every k periods to the
  // tolerance (still not converged: the harmonics are those of the last k periods); 0 when it
  // repeats within none of max_period_multiple.
  int period_multiple = 0;
  // Each period's first harmonic a1 - i b1 (x = Re(z e^{i omega t}) at the forcing frequency), one
  // row per period over the last envelope_periods (the last period alone when converged: the
  // earlier ones are its transient), one column per tracked DOF [m]; and per tracked DOF the
  // smallest and largest of their moduli (columns min, max) [m].
  Eigen::MatrixXcd period_harmonics;
  Eigen::MatrixXd envelope;
  std::string failure;        // cap reached (with the change) or a failed Newmark step; empty when converged
  long total_iterations = 0;  // Newton iterations over the run
  int max_iterations = 0;     // most Newton iterations in one step
  // Last period: each contact's samples at steps_per_period + 1 instants (start and end included,
  // so a steady loop closes), the work done over it and the change of mechanical energy.
  std::vector<std::vector<ContactSample>> contacts;
  WorkLedger cycle_work;
  double energy_change = 0.0;  // [J]
  DynamicState final_state;    // at a whole number of periods: start the next frequency from it
};

// Harmonics 0..H by the DFT of whole periods of samples at theta_k = 2 pi k / n_t (each period n_t
// rows, one column per DOF, all periods alike): fills coefficients, amplitude and phase.
void fill_harmonics(const std::deque<Eigen::MatrixXd>& periods, int harmonics, SteadyState& out);

// Amplitude and phase of out.coefficients (c0, a_1, b_1, ... per row).
void fill_amplitude_and_phase(SteadyState& out);

// From `start` (its displacements, velocities and sliders; its time is reset to 0, where the load
// has the same value for any omega, so a sweep from the final state of the previous frequency sees
// a continuous load) or, without one, from static_initial_state(model, options.initial).
// Throws std::invalid_argument on invalid inputs; a failed step or static solve is reported in
// the result (converged == false), never thrown.
[[nodiscard]] SteadyState steady_state(const friction::FrictionModel& model, double omega_rad_s,
                                       const SteadyStateOptions& options,
                                       const std::optional<DynamicState>& start = std::nullopt);

}  // namespace bb::timeint
