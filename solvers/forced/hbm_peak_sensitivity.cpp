#include "forced/hbm_peak_sensitivity.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <optional>

#include "forced/hbm_response.hpp"
#include "hbm/fixed_frequency.hpp"

namespace bb {
namespace {

using cplx = std::complex<double>;

// The complex first-harmonic quantity whose modulus peaks (kind 0 in-phase, 1 out-of-phase, or
// the first response) and the one reported as the peak's amplitude, as peak_values reads them.
struct PeakSignals {
  cplx component, amplitude;
};

PeakSignals signals(const PreparedHbm& p, const Eigen::VectorXcd& z, int kind) {
  if (!p.ip_oop) return {z[p.responses.front()], z[p.responses.front()]};
  const auto [l, r] = *p.ip_oop;
  return {kind == 0 ? (z[l] + z[r]) / 2.0 : (z[r] - z[l]) / 2.0, z[r]};
}

// d|s| = Re(conj(s) ds) / |s|.
double modulus_derivative(cplx s, cplx ds) { return (std::conj(s) * ds).real() / std::abs(s); }

// The derivatives of the two moduli at one solution: per parameter, then omega last.
struct Slopes {
  std::vector<double> component, amplitude;
};

std::optional<Slopes> slopes_at(const PreparedHbm& p, const hbm::HarmonicBalance& system, int kind,
                                std::vector<hbm::ModelDerivative> derivatives, const hbm::HbmSolution& s) {
  if (!s.converged) return std::nullopt;
  std::vector<Eigen::MatrixXd> dq;
  try {
    derivatives.push_back(hbm::frequency_derivative(system.model(), s.omega));
    dq = hbm::response_sensitivity(system, s, derivatives);
  } catch (const std::exception&) {
    return std::nullopt;  // a singular Jacobian or a model without a frequency derivative
  }
  const PeakSignals v = signals(p, first_harmonic(system, s.x, s.omega), kind);
  if (!(std::abs(v.component) > 0.0) || !(std::abs(v.amplitude) > 0.0)) return std::nullopt;
  Slopes out;
  for (const Eigen::MatrixXd& d : dq) {
    const Eigen::VectorXcd dz = d.col(1).cast<cplx>() - cplx(0.0, 1.0) * d.col(2).cast<cplx>();
    const PeakSignals dv = signals(p, dz, kind);
    out.component.push_back(modulus_derivative(v.component, dv.component));
    out.amplitude.push_back(modulus_derivative(v.amplitude, dv.amplitude));
  }
  return out;
}

}  // namespace

void add_peak_sensitivities(const PreparedHbm& p, const hbm::HarmonicBalance& system, int kind,
                            const std::vector<hbm::ModelDerivative>& derivatives, bool at_band_end, HbmPeak& peak) {
  const size_t n = derivatives.size();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  peak.frequency_hz_dlog.assign(n, nan);
  peak.amplitude_dlog.assign(n, nan);
  if (!peak.solution.converged || n == 0) return;
  if (at_band_end) {
    if (const std::optional<Slopes> s = slopes_at(p, system, kind, derivatives, peak.solution))
      for (size_t j = 0; j < n; ++j) peak.frequency_hz_dlog[j] = 0.0, peak.amplitude_dlog[j] = s->amplitude[j];
    return;
  }
  const double w0 = peak.solution.omega;
  // Close enough that no stick/slip transition of the curve falls in between (Table XI at 100 N
  // has one 1e-4 w0 from its IP peak), far enough that the solves' 1e-9 tolerance does not show.
  const double dw = 1e-6 * w0;
  const auto at = [&](double omega) {
    return slopes_at(p, system, kind, derivatives, hbm::solve_at_frequency(system, omega, peak.solution.x));
  };
  const std::optional<Slopes> mid = slopes_at(p, system, kind, derivatives, peak.solution);
  const std::optional<Slopes> below = at(w0 - dw), above = at(w0 + dw);
  if (!mid || !below || !above) return;
  const double c_ww = (above->component[n] - below->component[n]) / (2.0 * dw);
  if (!(c_ww < 0.0)) return;  // not a smooth maximum: no implicit function
  for (size_t j = 0; j < n; ++j) {
    const double c_wp = (above->component[j] - below->component[j]) / (2.0 * dw);
    const double dw_star = -c_wp / c_ww;
    peak.frequency_hz_dlog[j] = dw_star / (2.0 * std::numbers::pi);
    peak.amplitude_dlog[j] = mid->amplitude[j] + mid->amplitude[n] * dw_star;
  }
}

}  // namespace bb
