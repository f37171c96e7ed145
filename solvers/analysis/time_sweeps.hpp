// The per-frequency sweeps of a time analysis (analysis/time_analysis.hpp), shared by its two
// methods: which DOFs they track, how a point's first harmonics enter a level, and the tables
// built from the levels (time_tables.cpp).
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <utility>
#include <vector>

#include "analysis/time_analysis.hpp"
#include "forced/hbm_level.hpp"

namespace bb {

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

// frf, peaks, peaks_linear, peaks_hbm (compare_harmonics) and time_cost from o.levels on
// `frequencies`; a peak resting on a frequency without a steady state sets o.failure (the first).
void add_sweep_tables(TimeOutcome& o, const TimeSpec& spec, const std::vector<double>& frequencies,
                      const std::optional<std::pair<Eigen::Index, Eigen::Index>>& pair);

// history, hysteresis_<contact> and hysteresis_summary from o.record.
void add_history_tables(TimeOutcome& o, const TimeSpec& spec);

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
