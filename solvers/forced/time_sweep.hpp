// The time-domain forced-response sweeps (thesis section 3.4), beside the harmonic balance's in the
// forced-response layer: one level's stepped sine by Newmark to the steady state at each frequency
// (each from the previous one's final state) or by shooting (forced/shooting_sweep.cpp), the
// linear stuck model on the same grid, and a time history at one frequency. The tables are the
// analysis's (analysis/time_analysis.hpp).
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "forced/hbm_level.hpp"
#include "forced/time_spec.hpp"
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

// The DOFs the sweeps track: the responses, then the IP/OOP pair where not among them (`pair`:
// their positions in `dofs`).
struct TrackedDofs {
  std::vector<Eigen::Index> dofs;
  std::optional<std::pair<Eigen::Index, Eigen::Index>> pair;
};

TrackedDofs tracked_dofs(const PreparedHbm& p);

// Frequency i of `level` from the coefficients of the tracked DOFs (layout of timeint/steady_state.hpp):
// the responses' first-harmonic amplitudes and the IP/OOP components. False when they are not finite.
bool store_first_harmonics(TimeLevel& level, Eigen::Index i, const Eigen::MatrixXd& coefficients,
                           const TrackedDofs& tracked, Eigen::Index responses);

// The largest relative span, (max - min) / max, over the last periods of a march, of the
// first-harmonic amplitudes the peaks are read from: the IP and OOP components of the pair, else
// the responses. NaN without the periods' harmonics.
double peak_quantity_span(const timeint::SteadyState& s, const TrackedDofs& tracked, Eigen::Index responses);

// Whether frequencies without a steady state (newmark) or periodic solution (shooting on the Newmark
// map) are marched: the frf table then says what their motion did (change, period, envelope).
bool marches(const TimeSpec& spec);

// Whether frequency i of a level's stepped sine, not steady, counts as steady in its first harmonic
// (TimeSpec::envelope_tolerance): what the peaks and the report accept.
bool steady_first_harmonic(const TimeLevel& level, const TimeSpec& spec, Eigen::Index i);

// One level's sweep on `frequencies` (the steady-state options `options`: DOFs, steps, harmonics,
// tolerance), with the harmonic balance on the same grid where spec.compare_harmonics > 0 and the
// linear stuck model.
TimeLevel sweep_level(const PreparedHbm& p, const TimeSpec& spec, const timeint::SteadyStateOptions& options,
                      const TrackedDofs& tracked, const std::vector<double>& frequencies, double force,
                      const HbmProgress& progress);

// The steady state at history_hz by Newmark and history_cycles periods after it, every step recorded.
TimeHistoryRecord record_history(const PreparedHbm& p, const TimeSpec& spec,
                                 const timeint::SteadyStateOptions& options);

// The periodic responses of one level by shooting (timeint/shooting.hpp), each frequency started
// from the previous one's periodic state. On the Newmark map with the harmonic balance of the same
// grid (level.hbm), its solution at the frequency is tried first: the periodic motion it
// approximates, if there is one, whatever branch the previous frequency was on. Where Newton finds
// none on the Newmark map, `march` (max_cycles, steady_tolerance) marches from that start: a motion
// that settles is shot again from its orbit, one that does not keeps its change, period multiple and
// envelope in the level (no stable periodic solution there).
void periodic_sweep(TimeLevel& level, const PreparedHbm& p, const TimeSpec& spec, const friction::FrictionModel& model,
                    const TrackedDofs& tracked, Eigen::Index responses, const timeint::SteadyStateOptions& march,
                    const HbmProgress& progress);

// The periodic response at history_hz by shooting, history_cycles copies of its period recorded.
TimeHistoryRecord periodic_history(const PreparedHbm& p, const TimeSpec& spec);

}  // namespace bb
