// Identifying a friction contact from a measured frequency response: the tangential stiffness kt
// and friction coefficient mu of the friction oscillator (friction_oscillator_hbm.cpp) fitted to
// response amplitudes by weighted least squares (Ceres, in log space, bounded), with their standard
// deviations and correlation.
//
// The "measurement" here is the model itself at kt = 1e6 N/m, mu = 0.3, so the fit must return
// them; with rig data the evaluator below reads the same points from the measured curve instead.
#include <bladebench/hbm/fixed_frequency.hpp>
#include <bladebench/hbm/harmonic_balance.hpp>
#include <bladebench/identify/least_squares_fit.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

namespace {

// First-harmonic amplitude [m] of the oscillator at each frequency [Hz], swept upwards.
std::vector<double> response(double kt, double mu, const std::vector<double>& frequencies_hz) {
  bb::friction::FrictionModel model;
  model.mass = Eigen::MatrixXd::Constant(1, 1, 1.0);
  model.damping = Eigen::MatrixXd::Constant(1, 1, 10.0);
  model.stiffness = Eigen::MatrixXd::Constant(1, 1, 1e6);
  model.contacts.push_back({.point = {.kn = 1e6, .kt = kt, .mu = mu, .n0 = 30.0},
                            .tangential = Eigen::RowVectorXd::Ones(1),
                            .normal = Eigen::RowVectorXd::Zero(1)});
  model.harmonic_load = Eigen::VectorXcd::Constant(1, 5.0);
  const bb::hbm::HarmonicBalance system(model, {.harmonics = 3});
  std::vector<double> amplitudes;
  std::optional<Eigen::VectorXd> previous;
  for (double f : frequencies_hz) {
    const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(system, 2 * std::numbers::pi * f, previous);
    if (!s.converged) throw std::runtime_error(s.failure);  // the fit treats a failed run as a failed step
    previous = s.x;
    amplitudes.push_back(std::hypot(s.x[1], s.x[2]));
  }
  return amplitudes;
}

}  // namespace

int main() {
  std::vector<double> frequencies;
  for (double f = 170.0; f <= 230.0; f += 5.0) frequencies.push_back(f);
  const std::vector<double> measured = response(1e6, 0.3, frequencies);

  // The parameters: a name, bounds (> 0: the fit works on their logarithms) and a start.
  bb::CalibrationSpec spec;
  spec.parameters = {{"kt", 1e5, 1e7, 2.5e6}, {"mu", 0.05, 2.0, 0.6}};
  spec.max_iterations = 40;
  spec.threads = 1;
  // The evaluator: fitted points (measured, computed, sigma) at the given parameter values.
  const bb::FitEvaluator evaluate = [&](const std::vector<double>& p, bool) {
    const std::vector<double> computed = response(p[0], p[1], frequencies);
    std::vector<bb::FitPoint> points;
    for (size_t i = 0; i < frequencies.size(); ++i)
      points.push_back(
          {"sweep", "amplitude", "amplitude", frequencies[i], measured[i], computed[i], 0.02 * measured[i], false, {}});
    return points;
  };
  const bb::CalibrationOutcome fit = bb::fit_parameters(spec, evaluate, false, static_cast<int>(frequencies.size()));
  std::printf("%s after %zu iterations, %d model runs\n", fit.converged ? "converged" : "not converged",
              fit.history.size(), fit.residual_evaluations);
  for (size_t j = 0; j < spec.parameters.size(); ++j)
    std::printf("%s = %.6g +- %.2g (start %.3g)\n", spec.parameters[j].path.c_str(), fit.values[j], fit.std_devs[j],
                spec.parameters[j].start);
  for (const std::string& w : fit.warnings) std::printf("warning: %s\n", w.c_str());
  const bool recovered = std::abs(fit.values[0] / 1e6 - 1) < 1e-4 && std::abs(fit.values[1] / 0.3 - 1) < 1e-4;
  return fit.converged && recovered ? 0 : 1;
}
