// What a time-domain forced-response analysis computes (thesis section 3.4): the model, contacts,
// damper, forces, levels and frequency grid of a harmonic-balance analysis (hbm_spec.hpp),
// integrated by Newmark to the steady state at each frequency (stepped sine), plus time histories
// and hysteresis loops at one frequency, and the harmonic balance at the same frequencies.
#pragma once
#include <optional>

#include "forced/hbm_spec.hpp"

namespace bb {

struct TimeSpec {
  // newmark: march period after period until the motion repeats (steady_tolerance, max_cycles).
  // shooting: Newton on the period map of the exact flow (timeint/shooting.hpp), with the system's
  // tolerance and max_iterations; steps_per_period sub-intervals bracket the transitions.
  enum class Method { newmark, shooting };
  Method method = Method::newmark;
  // The period map shooting solves on: the exact piecewise-linear flow (timeint/shooting.hpp: no
  // time-step error, but a model with fast modes is cut into many pieces per period), or the Newmark
  // / HHT-alpha step (timeint/newmark_shooting.hpp: a fixed cost per period, its step error, alpha
  // damping the modes the step does not resolve).
  enum class PeriodMap { exact, newmark };
  PeriodMap period_map = PeriodMap::exact;
  bool floquet = false;  // shooting only: Floquet multipliers and stability per frequency
  // Shooting on the exact flow only: a stuck contact held rigidly (Coulomb's law; its kt unused)
  // instead of the Jenkins spring (set by the parser where every contact has law = "coulomb",
  // friction/coulomb_law.hpp).
  bool rigid_stick = false;
  HbmSpec system;                  // the grid sweep (frequency_hz, step_hz), levels, model; harmonics = DFT harmonics
  int steps_per_period = 128;      // dt = T / steps_per_period (eq 3.42)
  int max_cycles = 2000;           // per frequency, then the point is reported as not steady
  double steady_tolerance = 1e-6;  // cycle-to-cycle change, relative (timeint/steady_state.hpp)
  // newmark: a frequency whose motion repeats within no period up to max_period_multiple, but whose
  // tracked responses' first-harmonic amplitudes span at most this fraction over the last periods
  // (timeint::SteadyState::envelope), counts as steady in its first harmonic: what a rig's stepped
  // sine reads from a motion that never repeats exactly. 0: only a motion that repeats counts.
  double envelope_tolerance = 0.0;
  // A peak resting on a frequency that is not steady stops the run (SolverError). Not a case key:
  // the time-step study turns it off, since it measures the error of such unconverged settings.
  bool require_steady_peaks = true;
  double alpha = 0.0;                // HHT-alpha in [-1/3, 0]; 0 = average acceleration
  std::optional<double> history_hz;  // record histories and hysteresis loops at this frequency
  int history_cycles = 2;            // whole periods recorded there
  int compare_harmonics = 0;         // > 0: harmonic balance with this H at the same frequencies
};

}  // namespace bb
