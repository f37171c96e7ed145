#include "forced/hbm_nonlinear_modes.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <optional>
#include <utility>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "forced/hbm_response.hpp"
#include "friction/state_fractions.hpp"

namespace bb {
namespace {

using Eigen::Index;
using Complex = std::complex<double>;

// First-harmonic complex amplitudes Z = a1 - i b1 of every DOF.
Eigen::VectorXcd mode_first_harmonic(const hbm::NonlinearModePoint& p) {
  return p.coefficients.col(1).cast<Complex>() - Complex(0.0, 1.0) * p.coefficients.col(2).cast<Complex>();
}

// What the tables need of one backbone point.
struct BackbonePoint {
  double amplitude, frequency_hz, damping_ratio;
  double force_for_peak;           // Fe whose forced peak sits at this amplitude [N]
  std::vector<double> responses;   // |Z| of each response [m]
  double ip = kNan, oop = kNan;    // components with ip_oop [m]
  double stick = 0.0, lift = 0.0;  // fractions of the period, mean over the contacts
};

BackbonePoint backbone_point(const PreparedHbm& p, const hbm::NonlinearModePoint& pt) {
  BackbonePoint b;
  b.amplitude = pt.modal_amplitude;
  b.frequency_hz = pt.omega / kTwoPi;
  b.damping_ratio = pt.damping_ratio();
  const Eigen::VectorXcd z = mode_first_harmonic(pt);
  // |psi^H F| per newton of the first force, psi = Z / a.
  const double modal_force = std::abs(z.dot(p.model.harmonic_load)) / pt.modal_amplitude;
  b.force_for_peak = modal_force > 0 ? pt.kappa * pt.omega * pt.modal_amplitude / modal_force : kNan;
  for (Index r : p.responses) b.responses.push_back(std::abs(z[r]));
  if (p.ip_oop) {
    b.ip = peak_values(p, z, 0).component;
    b.oop = peak_values(p, z, 1).component;
  }
  for (const friction::AftResult& a : pt.contacts) {  // every contact has the same samples
    const friction::StateFractions f = friction::state_fractions(a.state);
    b.stick += f.stick / static_cast<double>(pt.contacts.size());
    b.lift += f.lift_off / static_cast<double>(pt.contacts.size());
  }
  return b;
}

// The point of the backbone where force_for_peak first reaches fe, interpolated linearly in
// log(force) between the two points that bracket it; nullopt when no segment does.
std::optional<std::pair<size_t, double>> crossing(const std::vector<BackbonePoint>& bb, double fe) {
  for (size_t i = 1; i < bb.size(); ++i) {
    const double f0 = bb[i - 1].force_for_peak, f1 = bb[i].force_for_peak;
    if (!(f0 > 0) || !(f1 > 0)) continue;
    if ((f0 - fe) * (f1 - fe) <= 0 && f0 != f1) return std::pair{i, std::log(fe / f0) / std::log(f1 / f0)};
  }
  return std::nullopt;
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

}  // namespace

HbmNonlinearModes trace_nonlinear_modes(const PreparedHbm& p, const std::vector<HbmLevel>& levels,
                                        const HbmSpec& spec) {
  HbmNonlinearModes o;
  if (!spec.nonlinear_modes) return o;
  const NonlinearModesSpec& nm = *spec.nonlinear_modes;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> amplitudes(static_cast<size_t>(nm.points));
  for (int i = 0; i < nm.points; ++i)
    amplitudes[static_cast<size_t>(i)] =
        nm.amplitude_min * std::pow(nm.amplitude_max / nm.amplitude_min, static_cast<double>(i) / (nm.points - 1));
  hbm::NonlinearModeOptions options;
  options.harmonics = spec.harmonics;
  options.aft.samples = spec.time_samples;
  options.aft.resolve_events = spec.aft_events;
  Eigen::VectorXd static_guess;
  if (p.damper_static) static_guess = p.damper_static->q;
  for (int mode : nm.linear_modes) {
    if (mode > p.model.mass.rows())
      throw InputError(fmt::format("{}: 'analysis.nonlinear_modes.linear_modes': mode {} of a model with {} DOFs",
                                   nm.at.where(), mode, p.model.mass.rows()));
    hbm::NonlinearModeBranch b = hbm::trace_nonlinear_mode(p.model, mode, amplitudes, static_guess, options);
    if (b.points.empty()) throw SolverError(b.failure);
    o.branches.push_back(std::move(b));
  }
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::vector<std::string> cols = {"point",        "mode",          "modal_amplitude",
                                   "frequency_hz", "damping_ratio", "force_for_peak_n"};
  for (const std::string& r : p.response_names) cols.push_back(r + "_amp_m");
  if (p.ip_oop) cols.insert(cols.end(), {"ip_component_m", "oop_component_m"});
  cols.insert(cols.end(), {"stick", "lift_off", "iterations"});
  std::vector<std::vector<double>> rows, peak_rows;
  std::vector<std::vector<BackbonePoint>> backbones;
  for (const hbm::NonlinearModeBranch& b : o.branches) {
    std::vector<BackbonePoint>& bb = backbones.emplace_back();
    for (const hbm::NonlinearModePoint& pt : b.points) {
      const BackbonePoint x = bb.emplace_back(backbone_point(p, pt));
      std::vector<double> row = {static_cast<double>(rows.size() + 1),
                                 static_cast<double>(b.linear_mode),
                                 x.amplitude,
                                 x.frequency_hz,
                                 x.damping_ratio,
                                 x.force_for_peak};
      row.insert(row.end(), x.responses.begin(), x.responses.end());
      if (p.ip_oop) row.insert(row.end(), {x.ip, x.oop});
      row.insert(row.end(), {x.stick, x.lift, static_cast<double>(pt.iterations)});
      rows.push_back(row);
    }
  }
  o.tables.emplace("nonlinear_modes", table_from_rows("nonlinear_modes", cols, rows));
  if (nm.peaks.empty()) return o;

  // The amplitude compared: with ip_oop the peak's component (IP |Z_l + Z_r| / 2, OOP |Z_r - Z_l| / 2),
  // which isolates one mode of a symmetric pair, else the first response's.
  const auto amplitude_of = [&](const BackbonePoint& x, const std::string& kind) {
    return kind == "ip" ? x.ip : kind == "oop" ? x.oop : x.responses.front();
  };
  for (size_t l = 0; l < levels.size(); ++l) {
    const HbmLevel& level = levels[l];
    for (size_t m = 0; m < nm.linear_modes.size(); ++m) {
      const std::string kind = nm.peaks[m] == "ip" ? "IP" : nm.peaks[m] == "oop" ? "OOP" : "peak";
      const HbmPeak* peak = nullptr;
      for (const HbmPeak& pk : level.peaks)
        if (pk.kind == kind) peak = &pk;
      std::vector<double> row = {static_cast<double>(10 * (l + 1) + m + 1), static_cast<double>(l + 1), level.force,
                                 static_cast<double>(nm.linear_modes[m])};
      double a = kNan, hz = kNan, amp = kNan;
      if (const auto c = crossing(backbones[m], level.force)) {
        const BackbonePoint &x0 = backbones[m][c->first - 1], &x1 = backbones[m][c->first];
        a = std::exp(lerp(std::log(x0.amplitude), std::log(x1.amplitude), c->second));
        hz = lerp(x0.frequency_hz, x1.frequency_hz, c->second);
        amp =
            std::exp(lerp(std::log(amplitude_of(x0, nm.peaks[m])), std::log(amplitude_of(x1, nm.peaks[m])), c->second));
      }
      const double sweep_hz = peak ? peak->frequency_hz : kNan, sweep_amp = peak ? peak->component : kNan;
      row.insert(row.end(), {a, hz, amp, sweep_hz, sweep_amp, hz / sweep_hz - 1, amp / sweep_amp - 1});
      peak_rows.push_back(row);
    }
  }
  o.tables.emplace("nonlinear_mode_peaks",
                   table_from_rows("nonlinear_mode_peaks",
                                   {"key", "level", "fe_n", "mode", "modal_amplitude", "predicted_hz",
                                    "predicted_amp_m", "sweep_hz", "sweep_amp_m", "hz_error", "amp_error"},
                                   peak_rows));
  return o;
}

}  // namespace bb
