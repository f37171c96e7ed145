// The [calibration] section of a case: which numeric case values to identify, within which
// bounds, against which checks' reference data.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cases/case_spec.hpp"

namespace bb {

struct CalibrationParameter {
  std::string path;     // dotted path of a number in the case file, e.g. "mesh.dimensions.L_a"
  double lower = 0.0;   // bounds, > 0: parameters are fitted in log space
  double upper = 0.0;
  double start = 0.0;   // the value in the case file
};

struct CalibrationSpec {
  std::vector<CalibrationParameter> parameters;
  std::vector<std::string> fit_checks;  // [[check]] names whose entries become residuals
  double relative_uncertainty = 0.01;   // sigma of each reference value, relative
  std::map<std::string, double> check_uncertainties;  // per-check override of relative_uncertainty
  std::string loss = "none";            // none | huber | cauchy
  double loss_scale = 1.0;              // in units of sigma
  int max_iterations = 50;
  // Converged when the cost changes by less than this relative amount in a step (Ceres's
  // function_tolerance); models with solver noise (peaks of a nonlinear sweep) need a looser one.
  double function_tolerance = 1e-10;
  // Relative step of the central differences (in log space). Models whose response is only
  // piecewise smooth (AFT sampling of friction contacts) need a step that spans their kinks.
  double derivative_step = 1e-4;
  // Multi-start: the case's values, then starts - 1 points of a Latin hypercube in log space
  // within the bounds (seeded, so a run repeats); the lowest final cost wins.
  int starts = 1;
  unsigned seed = 1;
  SourceLocation at;
};

// Sigma of the entries of fit check `name`.
double uncertainty_of(const CalibrationSpec& c, const std::string& name);

// Reads [calibration] from a case file's table; std::nullopt when absent. Checks that every
// path names an existing number inside its bounds and every fit check exists. Throws InputError.
std::optional<CalibrationSpec> parse_calibration(const toml::table& root, const std::filesystem::path& file,
                                                 const CaseSpec& spec);

// The number at a dotted path ("a.b.c"), or nullptr.
toml::node* node_at_path(toml::table& root, const std::string& path);

}  // namespace bb
