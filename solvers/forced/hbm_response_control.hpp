// A response-controlled stepped sine (HbmSpec::response_controls): at each frequency, in the order
// stepped, the force that holds one response at the asked amplitude (hbm/response_control.hpp),
// each point from the one before; and the smallest force over the curve, refined between its
// neighbours. Rigs test joints and dampers this way because the curve has no fold: the force
// needed for a given amplitude is single-valued where the force-controlled response jumps.
#pragma once
#include <Eigen/Dense>

#include <limits>
#include <string>
#include <vector>

#include "forced/hbm_level.hpp"

namespace bb {

struct HbmControlled {
  std::string name;
  int harmonics = 0, samples = 0;
  // The converged points in the order stepped: index in the spec (0-based), frequency, the held
  // displacement amplitude [m], the force's amplitude [N] and phase [deg] (the held response at 0).
  std::vector<size_t> point;
  std::vector<double> frequency_hz, held_m, force, force_phase_deg;
  // points x responses: first-harmonic amplitude [m], phase to the force [deg], largest |u(t)| [m].
  Eigen::MatrixXd amplitude, phase_deg, excursion;
  std::vector<double> residual;  // ||R|| of the extended system [N]
  std::vector<int> iterations;
  std::vector<double> failed_hz;
  std::vector<std::string> failures;
  int total_iterations = 0;
  // The smallest force over the curve: golden section between the neighbours of the smallest point
  // (NaN with fewer than three points, or at an end of the curve, where it is the end's).
  double min_force = std::numeric_limits<double>::quiet_NaN();
  double min_frequency_hz = std::numeric_limits<double>::quiet_NaN();
  double min_phase_deg = std::numeric_limits<double>::quiet_NaN();  // of the held response to the force there
  bool min_interior = false;
  double seconds = 0.0;
};

HbmControlled run_response_control(const PreparedHbm& p, const HbmSpec& spec, const ResponseControlSpec& control,
                                   const HbmProgress& progress = {});

}  // namespace bb
