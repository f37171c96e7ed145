// The [calibration] section of a case: which numeric case values to identify, within which
// bounds, against which data: the reference values of chosen checks and/or measured curves read
// from CSV files with units (identify/measured_data.hpp).
#pragma once
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/source_location.hpp"
#include "identify/measured_data.hpp"

namespace bb {

struct CalibrationParameter {
  std::string path;  // dotted path of a number in the case file, e.g. "mesh.dimensions.L_a" (cases/case_parameter.hpp)
  double lower = 0.0;  // bounds; > 0 for a log scale
  double upper = 0.0;
  double start = 0.0;  // the value in the case file
  // What the fit varies: log(p) (relative steps whatever the unit; the default for positive
  // bounds), or p / (upper - lower) (linear: a parameter that may be zero or negative, e.g. an
  // Iwan joint's exponent chi in (-1, 0]). Starts, steps and the covariance are taken in it.
  enum class Scale { log, linear } scale = Scale::log;
  double to_fit(double value) const { return scale == Scale::log ? std::log(value) : value / (upper - lower); }
  double from_fit(double x) const { return scale == Scale::log ? std::exp(x) : x * (upper - lower); }
  // d value / d x, at the value.
  double value_per_fit(double value) const { return scale == Scale::log ? value : upper - lower; }
  // A stated prior (value, 1-sigma, in the parameter's units): the residual (p - value) / sigma
  // joins the fit, so the parameter is held near what is known of it instead of fixed or free.
  struct Prior {
    double value = 0.0, sigma = 0.0;
  };
  std::optional<Prior> prior = {};
};

// One [[calibration.data]] block: a measured curve and the result table that models it.
struct CalibrationData {
  std::string name;                            // label in reports (default: the file's stem)
  MeasuredData data;                           // read and validated when the case is parsed
  std::string table;                           // result table holding the computed curve
  std::map<std::string, std::string> columns;  // data column -> result column
  // Sigmas when the file has no *_sigma column: relative to each amplitude (peaks, frf), relative
  // to the peak frequency (peaks), absolute in radians (phase), relative to the largest |force| of
  // the loop (hysteresis: a relative sigma per point would blow up where the force crosses zero),
  // relative to each measured force (a response-controlled curve's).
  double amplitude_uncertainty = 0.02;
  double frequency_uncertainty = 0.001;
  double phase_uncertainty = 0.035;  // 2 degrees
  double force_uncertainty = 0.02;
  // Named in [calibration] hold_out: not fitted; predicted at the identified values and reported
  // per curve (cross-validation).
  bool held_out = false;
  SourceLocation at;
};

struct CalibrationSpec {
  std::vector<CalibrationParameter> parameters;
  std::vector<std::string> fit_checks;                // [[check]] names whose entries become residuals
  std::vector<CalibrationData> data;                  // measured curves whose points become residuals
  double relative_uncertainty = 0.01;                 // sigma of each reference value, relative
  std::map<std::string, double> check_uncertainties;  // per-check override of relative_uncertainty
  std::string loss = "none";                          // none | huber | cauchy
  double loss_scale = 1.0;                            // in units of sigma
  int max_iterations = 50;
  // Converged when the cost changes by less than this relative amount in a step (Ceres's
  // function_tolerance); models with solver noise (peaks of a nonlinear sweep) need a looser one.
  double function_tolerance = 1e-10;
  // Step of the central differences in the log values, i.e. the relative step of every parameter
  // whatever its unit. Models whose response is only piecewise smooth (AFT sampling of friction
  // contacts) need a step that spans their kinks.
  double derivative_step = 1e-4;
  // "auto": analytic derivatives when the model gives them (every fitted point from frf data of an
  // hbm analysis, every parameter a path hbm/sensitivity.hpp differentiates), else central
  // differences; "analytic": the same, and peaks (data and checks of the peaks table) by how each
  // peak moves (forced/hbm_peak_sensitivity.hpp); "numeric": always central differences. Peaks are
  // not in "auto": on Table XI their exact local slopes, across the jumps of a rugged cost, led
  // the fit into a worse minimum than the 1 % differences (bench/README.md).
  std::string derivatives = "auto";
  // Multi-start: the case's values, then starts - 1 points of a Latin hypercube in log space
  // within the bounds (seeded, so a run repeats); the lowest final cost wins.
  int starts = 1;
  unsigned seed = 1;
  // Starts solved at once (each its own problem; the outcome is the serial one): 0 = one per core.
  // The threads left to each start (threads / starts at once) run its central differences.
  int threads = 0;
  // An independent model (e.g. the time integration) run with the identified values at the same
  // parameter paths; its checks must pass for the identification to count (empty: none).
  std::filesystem::path cross_check;
  // The cross-check's result tables written with a band column beside every column the parameters
  // move (`<column>_band_1sigma`: the covariance carried by central differences, 2 k more runs).
  bool cross_check_bands = false;
  // Probability of the two-sided prediction bands written with the predicted curves.
  double band_level = 0.95;
  // [calibration.sampler]: the posterior sampled around the optimum by an affine-invariant ensemble
  // (identify/ensemble_sampler.hpp), likelihood exp(-cost / max(1, reduced chi-square)) within the
  // bounds; its spread of every predicted point is a second band beside the linearised one.
  struct Sampler {
    int walkers = 0;  // even, >= 2 x parameters; 0: the smallest even count >= 4 x parameters
    int steps = 600;
    int burn_in = -1;       // -1: half of steps
    int predictions = 100;  // posterior samples the predicted curves are evaluated at
    unsigned seed = 1;
  };
  std::optional<Sampler> sampler;
  SourceLocation at;
};

// Sigma of the entries of fit check `name`.
double uncertainty_of(const CalibrationSpec& c, const std::string& name);

}  // namespace bb
