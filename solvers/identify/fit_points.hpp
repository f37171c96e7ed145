// The points a calibration fits: each a measured value, the model's value at the same place and a
// stated uncertainty. They come from the entries of fitted checks (a reference value per entry) and
// from measured curves (identify/measured_data.hpp) matched to the case's result tables.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "checks/checks.hpp"
#include "identify/calibration_spec.hpp"
#include "results/table.hpp"

namespace bb {

struct FitPoint {
  std::string set;        // check name or data-set name
  std::string label;      // e.g. "frequency 172.4 Hz: amplitude"
  std::string quantity;   // the fitted column of the data ("amplitude", "phase", ...), or "check"
  double x = 0.0;         // abscissa in the data (frequency, force level, displacement), for plots
  double measured = 0.0;  // SI
  double computed = 0.0;  // SI
  double sigma = 0.0;     // 1-sigma of measured, SI, > 0
  bool angle = false;     // the misfit is wrapped into (-pi, pi]
  // d residual / d log p_j per calibration parameter, when the result table carries the model's
  // log-sensitivity columns (analysis/hbm_analysis.hpp); empty otherwise.
  std::vector<double> gradient;
  bool held_out = false;  // a point of a held-out curve: predicted, not fitted (CalibrationData::held_out)
  // The unit its values are shown in ("m", "m/N", "Hz", "N", "deg", ... ; empty: none known); SI
  // in the fields above, degrees shown for an angle (display_scale).
  std::string unit = {};
  // 1-sigma of `computed` carried from the parameters' covariance (identify/prediction_bands.hpp),
  // SI; NaN where not computed.
  double band = std::numeric_limits<double>::quiet_NaN();
  // The same from posterior samples (identify/posterior_bands.hpp): the spread of `computed`.
  double sampled_band = std::numeric_limits<double>::quiet_NaN();

  double misfit() const;         // computed - measured (wrapped for angles)
  double display_scale() const;  // 180 / pi for an angle, else 1
  double residual() const { return misfit() / sigma; }
};

// Entries of a fitted check: r = (computed / reference - 1) / sigma_rel. With `table` (the check's
// result table) and `parameters` (case paths), an entry gets a gradient when its computed row has
// the column "<compared column>_dlog_<path>" for every one of them.
std::vector<FitPoint> check_points(const std::vector<CheckEntry>& entries, const CalibrationSpec& cal,
                                   const ResultTable* table = nullptr, const std::vector<std::string>& parameters = {});

// The points of one measured curve against the case's result tables:
//   peaks       per data row, the result row whose force column equals the row's force (to 1e-9
//               relative); frequency and amplitude as mapped.
//   frf         the mapped result columns interpolated linearly at each measured frequency (the
//               computed frequencies must increase or decrease and cover the data's range). Data
//               with a force per point map `force` to a stepped sine's force column: each table
//               row at a data frequency must carry that row's force (a failed point is
//               interpolated over, between its neighbours' forces). Against a response-controlled
//               table (one with a held_m column) the force is what was measured: force and phase
//               are fitted, the amplitude (what the rig held) is not.
//   hysteresis  per measured point, the computed force on the branch of the loop that moves the
//               same way (the direction from the neighbouring measured points), interpolated at
//               the measured displacement; clamped to the branch's ends outside its range.
// Throws InputError (naming the case's data block and the data row) when a table or column is
// missing or the data lie outside the computed curve.
// `parameters`: case paths; frf and peaks points get a gradient when the table has the column
// "<result column>_dlog_<path>" for every one of them (frf: interpolated like the value).
std::vector<FitPoint> data_points(const CalibrationData& d, const ResultTables& tables,
                                  const std::vector<std::string>& parameters = {});

// InputError (as data_points) when the case computes no table or column the data block names:
// what `run` checks of a [calibration], whose values it does not fit.
void require_data_columns(const CalibrationData& d, const ResultTables& tables);

// SolverError when a fitted point has no computed value because its curve's table records no
// solution next to it (a stepped sine's failed point, a row of NaN with its "failure"): named
// with the frequency and the solver's failure (its residual). For the start of a fit; inside it,
// such a point makes the evaluation fail and Ceres rejects the step (never a smaller residual).
void require_solved_points(const std::vector<FitPoint>& points, const CalibrationSpec& cal, const ResultTables& tables);

}  // namespace bb
