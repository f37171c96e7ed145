// A stepped sine as a rig runs it (HbmSpec::stepped_sines): each point at its own frequency and
// force, solved from the point before, in the order stepped. What a calibration fits measured
// curves against when their force drifts, and what tells an up sweep from a down sweep.
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "forced/hbm_level.hpp"

namespace bb {

struct HbmSteppedSine {
  std::string name;
  int harmonics = 0, samples = 0;
  // The converged points, in the order stepped: their index in the spec (0-based), frequency and force.
  std::vector<size_t> point;
  std::vector<double> frequency_hz, force;
  Eigen::MatrixXd amplitude, phase_deg, excursion;  // points x responses (as HbmLevel)
  std::vector<double> residual;                     // ||R|| [N]
  std::vector<int> iterations;
  // Per path of spec.sensitivities: points x responses, p d|z|/dp [m] and p d phase/dp [deg].
  std::vector<Eigen::MatrixXd> amplitude_dlog, phase_dlog_deg;
  // Points that did not converge (frequency [Hz] and why); the next point starts from the last converged.
  std::vector<double> failed_hz;
  std::vector<std::string> failures;
  int total_iterations = 0;
  double seconds = 0.0;
};

// The first point from the linear limits (first_solution), each next from the last converged
// solution: Newton at the new frequency and force, then first_solution's fallbacks from it (a
// homotopy from the last converged force, longer solves). Never throws on non-convergence.
HbmSteppedSine run_stepped_sine(const PreparedHbm& p, const HbmSpec& spec, const SteppedSineSpec& sine,
                                const HbmProgress& progress = {});

}  // namespace bb
