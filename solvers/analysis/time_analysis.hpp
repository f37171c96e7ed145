// Time-domain forced response (thesis section 3.4): the model of a harmonic-balance analysis
// (analysis/hbm_level.hpp: reduced or lumped model, contacts, rigid damper seated by CF)
// integrated by Newmark with the implicit predictor-corrector contact (timeint/newmark.hpp) to the
// steady state at each frequency of a grid (stepped sine), each frequency starting from the
// previous one's final state; time histories and hysteresis loops at one frequency; and the
// harmonic balance at the same frequencies, for cross-validation.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/time_spec.hpp"
#include "forced/hbm_level.hpp"
#include "results/table.hpp"
#include "timeint/steady_state.hpp"

namespace bb {

struct TimeLevel {
  double force = 0.0;  // amplitude of the first force [N]
  std::vector<double> frequency_hz;
  Eigen::MatrixXd amplitude;         // frequencies x responses, first harmonic [m]
  Eigen::MatrixXd phase;             // the same harmonic's phase to the force, arg(a - i b) [rad]
  Eigen::MatrixXd components;        // frequencies x (IP, OOP) [m] when ip_oop is set
  std::vector<int> cycles;           // periods integrated per frequency
  std::vector<bool> steady;          // the cycle-to-cycle criterion was met (shooting: Newton converged)
  std::vector<std::string> failure;  // per frequency, why it is not steady (shooting: |R|, iterations)
  // Where marched (marches()), per frequency: the last cycle-to-cycle change, the periods after which the
  // motion repeats (timeint::SteadyState::period_multiple), each response's range of first-harmonic
  // amplitude over the last periods (frequencies x responses) [m], and the largest relative span
  // of that range over the tracked DOFs ((max - min) / max).
  std::vector<double> change;
  std::vector<int> period_multiple;
  Eigen::MatrixXd envelope_min, envelope_max;
  std::vector<double> envelope_span;
  // Shooting only, per frequency: the largest |q| of each response over the period [m], the
  // residual [m], transitions per period, and with floquet the largest multiplier's modulus.
  Eigen::MatrixXd largest;
  std::vector<double> residual, floquet_max;
  std::vector<int> transitions;
  long steps = 0, newton_iterations = 0;
  int max_step_iterations = 0;
  double seconds = 0.0;
  Eigen::MatrixXd linear, linear_components;  // the linear model (contacts as springs kn, kt) on the grid
  std::optional<HbmLevel> hbm;                // the harmonic balance at the same grid (compare_harmonics > 0)
};

struct TimeHistoryRecord {
  double frequency_hz = 0.0, force = 0.0;
  timeint::SteadyState steady;   // the steady state reached there
  timeint::TimeHistory history;  // history_cycles periods after it, every step recorded
};

struct TimeOutcome {
  ResultTables tables;
  PreparedHbm prepared;
  std::vector<TimeLevel> levels;
  std::optional<TimeHistoryRecord> record;
  double seconds = 0.0;
  // The first peak that rests on a frequency without a steady state (or periodic solution); its
  // row holds NaN for that peak, and the run has no verdict. Empty: every peak stands.
  std::string failure;
};

// Whether frequencies without a steady state (newmark) or periodic solution (shooting on the Newmark
// map) are marched: the frf table then says what their motion did (change, period, envelope).
bool marches(const TimeSpec& spec);

// Whether frequency i of a level's stepped sine, not steady, counts as steady in its first harmonic
// (TimeSpec::envelope_tolerance): what the peaks and the report accept.
bool steady_first_harmonic(const TimeLevel& level, const TimeSpec& spec, Eigen::Index i);

// Throws as prepare_hbm; a frequency that does not reach the steady state, or a Newmark step that
// fails, is reported in the tables (steady = 0, with the change or the message), never thrown; a
// peak resting on one is `failure`. The reduction goes through the model cache in `cache`, when given.
TimeOutcome run_time(const Model& model, const TimeSpec& spec, const HbmProgress& progress = {},
                     const ModelCacheSettings* cache = nullptr);

}  // namespace bb
