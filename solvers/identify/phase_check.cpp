#include "identify/phase_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "common/constants.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

double wrap(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

// The root mean square of angles within (-pi, pi]: bounded, so an outlier weighs little; a mean,
// since a lag's sign shows only near resonance (a phase near 0 or -180 degrees reads the same
// either way).
double rms(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum / static_cast<double>(v.size()));
}

// A phase along increasing frequency, unwrapped: its change from the first point to the last and
// its range.
struct Trend {
  double net = 0.0, span = 0.0;
};

Trend trend_of(const std::vector<double>& phase) {
  double u = phase.front(), lo = u, hi = u;
  for (size_t k = 1; k < phase.size(); ++k) {
    u += wrap(phase[k] - phase[k - 1]);
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  return {u - phase.front(), hi - lo};
}

std::string column_of(const CalibrationData& d) {
  const auto u = d.data.units.find("phase");
  return u == d.data.units.end() ? std::string("phase") : fmt::format("phase [{}]", u->second.symbol);
}

// What would make a phase 180 degrees off, for the message.
std::string shift_cause(const CalibrationData& d) {
  if (d.data.derivative == 2)
    return "its amplitude is an acceleration, whose phase is read as the acceleration's (moved by -180 deg to the "
           "displacement's): a displacement's phase given with it is 180 deg off";
  return "a displacement's phase given for an acceleration, or the force's sign reversed";
}

const char* direction(double net) { return net > 0 ? "rises" : "falls"; }

}  // namespace

std::vector<std::string> check_measured_phases(const CalibrationSpec& cal, const std::vector<FitPoint>& points) {
  std::vector<std::string> warnings;
  for (const CalibrationData& d : cal.data) {
    if (d.data.kind != DataKind::frf || !d.columns.count("phase")) continue;
    std::vector<const FitPoint*> phase;
    for (const FitPoint& p : points)
      if (p.set == d.name && p.quantity == "phase" && std::isfinite(p.computed) && std::isfinite(p.measured))
        phase.push_back(&p);
    if (phase.size() < 3) continue;
    std::stable_sort(phase.begin(), phase.end(), [](const FitPoint* a, const FitPoint* b) { return a->x < b->x; });
    std::vector<double> measured, computed, misfit, shifted, negated, both;
    double c = 0.0, s = 0.0;
    for (const FitPoint* p : phase) {
      measured.push_back(p->measured);
      computed.push_back(p->computed);
      misfit.push_back(p->misfit());
      shifted.push_back(wrap(p->misfit() - std::numbers::pi));
      negated.push_back(wrap(p->computed + p->measured));
      both.push_back(wrap(p->computed + p->measured - std::numbers::pi));
      c += std::cos(p->misfit());
      s += std::sin(p->misfit());
    }
    const Trend data = trend_of(measured), model = trend_of(computed);
    const double given = rms(misfit);
    const std::vector<std::pair<double, std::string>> alternatives{
        {rms(shifted), "180 deg off (" + shift_cause(d) + ")"},
        {rms(negated),
         "of the opposite sign (a lag written as a positive angle: the model's response lags "
         "the force, its phase falls through a resonance)"},
        {rms(both), "of the opposite sign and 180 deg off"}};
    const auto best = std::min_element(alternatives.begin(), alternatives.end());
    const std::string where = fmt::format("{}: calibration data '{}': column '{}' of {}", d.at.where(), d.name,
                                          column_of(d), d.data.file.string());
    if (data.span >= 90.0 * kRadPerDeg && given >= 45.0 * kRadPerDeg && best->first <= given / 3.0)
      throw InputError(fmt::format(
          "{} is {}: the measured phase lies {:.0f} deg from the model's at the start (rms of {} points), {:.0f} "
          "deg once corrected; correct the file's phase",
          where, best->second, given / kRadPerDeg, phase.size(), best->first / kRadPerDeg));
    const double n = static_cast<double>(phase.size());
    const double mean = std::atan2(s / n, c / n), length = std::hypot(s / n, c / n);
    if (std::abs(mean) >= 150.0 * kRadPerDeg && length >= 0.8)
      warnings.push_back(fmt::format(
          "{}: at the start the measured phase lies {:.0f} deg from the model's at every point (mean), and it changes "
          "by {:.0f} deg only over the curve: the start may be far from the data's resonance, or the phase is 180 "
          "deg off ({})",
          where, mean / kRadPerDeg, data.span / kRadPerDeg, shift_cause(d)));
    else if (data.net * model.net < 0.0 && std::abs(data.net) >= 90.0 * kRadPerDeg &&
             std::abs(model.net) >= 90.0 * kRadPerDeg)
      warnings.push_back(fmt::format(
          "{}: the measured phase {} by {:.0f} deg over the curve where the model's {} by {:.0f} deg at the start: "
          "is the lag of the opposite sign?",
          where, direction(data.net), std::abs(data.net) / kRadPerDeg, direction(model.net),
          std::abs(model.net) / kRadPerDeg));
  }
  return warnings;
}

}  // namespace bb
