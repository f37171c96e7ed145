#include "identify/model_comparison.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>

#include "identify/prediction_bands.hpp"

namespace bb {

ModelScore score_calibration(const std::string& name, const CalibrationOutcome& o) {
  ModelScore s;
  s.name = name;
  s.parameters = static_cast<int>(o.values.size());
  s.converged = o.converged;
  double held2 = 0.0;
  for (const FitPoint& p : o.after) {
    if (p.set == "priors") continue;
    const double r = p.residual();
    if (p.held_out) {
      ++s.held_out_points;
      held2 += r * r;
      if (p.measured != 0.0 && !p.angle)
        s.held_out_largest_error = std::max(s.held_out_largest_error, std::abs(p.computed / p.measured - 1.0));
    } else {
      ++s.fitted_points;
      s.chi_square += r * r;
    }
  }
  s.aic = s.chi_square + 2.0 * s.parameters;
  s.bic = s.chi_square + s.parameters * std::log(std::max(1, s.fitted_points));
  s.held_out_rms = s.held_out_points ? std::sqrt(held2 / s.held_out_points) : NAN;
  if (const BandCoverage c = band_coverage(o.after, true); c.points > 0) s.band_coverage = c.share();
  s.cross_check_entries = static_cast<int>(o.cross_check.size());
  s.cross_check_passed = static_cast<int>(
      std::count_if(o.cross_check.begin(), o.cross_check.end(), [](const CheckEntry& e) { return e.pass; }));
  return s;
}

std::vector<std::string> fitted_sets(const CalibrationOutcome& o) {
  std::vector<std::string> out;
  for (const CalibrationData& d : o.spec.data)
    if (!d.held_out) out.push_back(d.name);
  return out;
}

std::string fold_hold_out_setting(const CalibrationOutcome& o, const std::string& set) {
  const auto quoted = [](const std::string& name) {
    std::string q = "\"";
    for (char c : name) {
      if (c == '"' || c == '\\') q += '\\';
      q += c;
    }
    return q + "\"";
  };
  std::vector<std::string> names;
  for (const CalibrationData& d : o.spec.data)
    if (d.held_out || d.name == set) names.push_back(quoted(d.name));
  return fmt::format("calibration.hold_out=[{}]", fmt::join(names, ", "));
}

void score_leave_one_out(ModelScore& s, const std::vector<CalibrationOutcome>& folds,
                         const std::vector<std::string>& left_out) {
  double sum2 = 0.0;
  long points = 0;
  s.folds = static_cast<int>(folds.size());
  s.folds_converged = 0;
  for (size_t i = 0; i < folds.size() && i < left_out.size(); ++i) {
    s.folds_converged += folds[i].converged ? 1 : 0;
    for (const FitPoint& p : folds[i].after)
      if (p.set == left_out[i]) {
        const double r = p.residual();
        sum2 += r * r;
        ++points;
      }
  }
  s.leave_one_out_rms = points ? std::sqrt(sum2 / static_cast<double>(points)) : NAN;
}

void rank_models(std::vector<ModelScore>& scores, const std::vector<const CalibrationOutcome*>& outcomes) {
  const auto sets = [](const CalibrationOutcome& o, bool held) {
    std::set<std::string> out;
    for (const CalibrationData& d : o.spec.data)
      if (d.held_out == held) out.insert(d.name);
    return out;
  };
  for (size_t k = 1; k < outcomes.size(); ++k)
    for (bool held : {false, true})
      if (sets(*outcomes[k], held) != sets(*outcomes[0], held))
        throw std::invalid_argument(
            fmt::format("'{}' {} other data sets than '{}': models are compared on the same data", scores[k].name,
                        held ? "holds out" : "fits", scores[0].name));
  std::vector<size_t> order(scores.size());
  std::iota(order.begin(), order.end(), 0);
  const bool by_folds =
      std::all_of(scores.begin(), scores.end(), [](const ModelScore& s) { return !std::isnan(s.leave_one_out_rms); });
  const auto key = [&](size_t i) {
    const ModelScore& s = scores[i];
    const double predicted = by_folds ? s.leave_one_out_rms : s.held_out_rms;
    return std::pair{std::isnan(predicted) ? 0.0 : predicted, s.bic};
  };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return key(a) < key(b); });
  for (size_t r = 0; r < order.size(); ++r) scores[order[r]].rank = static_cast<int>(r + 1);
}

}  // namespace bb
