// Frequency continuation of the harmonic balance (hbm/condensed_balance.hpp): tangent predictor and
// pseudo-arclength corrector in (x, omega) (Seydel, Practical Bifurcation and Stability Analysis,
// 3rd ed., section 4.4). Units: SI.
//
// R is only piecewise smooth (stick, slip and lift-off switch), so the path has corners. Where the
// corrector fails at a small step, the tangent of the piece beyond the kink is tried in both
// orientations (a corner can turn the path back in frequency: a non-smooth fold); where that fails
// the step shrinks, and below min_step a few larger steps over the kink are tried; if they fail
// the result says so (converged == false, with omega and |R|).
#pragma once
#include <Eigen/Dense>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hbm/condensed_balance.hpp"

namespace bb::hbm {

struct ContinuationProgress {
  int point = 0;           // index of the point just accepted
  double omega = 0.0;      // [rad/s]
  double amplitude = 0.0;  // max over contact DOFs of the first-harmonic amplitude [m]
  double step = 0.0;       // scaled arclength step used
  int iterations = 0;      // corrector iterations
};

struct ContinuationOptions {
  double omega_start = 0.0, omega_end = 0.0;  // [rad/s], > 0; either order
  // Arclength is measured in scaled variables (x / x_ref, omega / omega_start), x_ref the norm of the
  // harmonic part of the first solution (or amplitude_scale when > 0).
  double amplitude_scale = 0.0;
  // How far the path may run back past omega_start before it stops as failed [rad/s]; 0: half the
  // distance to omega_end.
  double omega_back = 0.0;
  double initial_step = 0.02;
  double min_step = 1e-6;  // below this after shrinking the continuation stops as failed
  double max_step = 0.5;
  double grow = 1.5;    // step factor after a corrector that converged in <= easy_iterations
  double shrink = 0.5;  // step factor after a failed corrector
  int easy_iterations = 4;
  int max_corrector_iterations = 25;
  int max_points = 5000;  // hard cap, then failure
  // A path that turns back and forth more often than this is wandering along the kinks of a
  // stick-slip solution set, not tracing a fold: it stops as failed. 0: no cap.
  int max_turning_points = 0;
  std::optional<Eigen::VectorXd> initial = std::nullopt;  // guess for the first point (e.g. from a static pre-solve)
  std::function<void(const ContinuationProgress&)> progress;  // called per accepted point; may be empty
};

struct ContinuationPoint {
  double omega = 0.0;
  Eigen::VectorXd x;
  double residual = 0.0;  // ||R|| [N]
  int iterations = 0;
  double step = 0.0;           // scaled arclength from the previous point (0 for the first)
  double tangent_omega = 0.0;  // d(omega / omega_start)/ds at the point; its sign changes at a fold
};

struct ContinuationResult {
  std::vector<ContinuationPoint> points;
  bool converged = false;  // reached omega_end
  std::string failure;     // with |R| and omega when not converged
  // Stopped because the path ran back past omega_back: the branch folds away from omega_end, and
  // no step size reaches omega_end along it.
  bool turned_back = false;
  int turning_points = 0;  // sign changes of d omega / ds along the path
  int corrector_iterations = 0, rejected_steps = 0;
  int jumps = 0;    // points reached by stepping over a kink after the step fell below min_step
  int corners = 0;  // points reached by turning at a kink onto the piece beyond it
  double amplitude_scale = 0.0;
};

[[nodiscard]] ContinuationResult continue_in_frequency(const HarmonicBalance& system,
                                                       const ContinuationOptions& options);

}  // namespace bb::hbm
