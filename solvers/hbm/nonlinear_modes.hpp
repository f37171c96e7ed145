// Nonlinear modes of a friction system (hbm/friction_system.hpp) by the extended periodic motion
// concept (Krack, "Nonlinear modal analysis of nonconservative systems: extension of the periodic
// motion concept", Computers & Structures 154, 2015): the free motion of
//   M q'' + (C - kappa M) q' + K q + g(q) = f_static
// is periodic for one kappa, the negative mass-proportional damping that makes up, over a cycle, for
// what the viscous damping and the contacts dissipate. Along the modal amplitude a, harmonic balance
// gives the frequency omega(a), the modal damping ratio D(a) = kappa / (2 omega) and the shape.
// Units: SI; a in m kg^(1/2) (q = a psi with psi's first harmonic mass-normalized).
//
// Unknowns: every DOF's 2H + 1 coefficients (layout of friction/aft.hpp), omega and kappa; equations:
// the harmonic balance of every DOF (no condensation: kappa changes the damping the condensation would
// fold in), psi_1^H M psi_1 = 1 (amplitude) and b_1 . M phi = 0 (phase, phi the stuck linear mode).
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "friction/aft.hpp"
#include "friction/friction_system.hpp"

namespace bb::hbm {

struct NonlinearModeOptions {
  int harmonics = 1;
  friction::AftOptions aft{};  // samples = 0: max(64, 16 (2H + 1)), as HbmOptions
  double tolerance = 1e-9;     // on the scaled residual (forces over k_max a, k_max the largest stuck stiffness)
  int max_iterations = 30;     // Newton iterations per amplitude
  int max_halvings = 6;        // halvings of a failed amplitude step before the amplitude is given up
  // Requested amplitudes given up in a row (each after its halvings) before the branch stops: at a
  // corner of the contact states (a contact that sticks throughout next to one that shakes down to
  // its Coulomb limit) Newton can stall at one amplitude and converge again past it.
  int max_skips = 3;
};

struct NonlinearModePoint {
  double modal_amplitude = 0.0;  // a [m kg^1/2]
  double omega = 0.0;            // [rad/s]
  double kappa = 0.0;            // [1/s]; modal damping ratio kappa / (2 omega)
  Eigen::MatrixXd coefficients;  // n x (2H + 1): q's harmonics [m]
  std::vector<friction::AftResult> contacts;
  double residual = 0.0;  // scaled
  int iterations = 0;
  double damping_ratio() const { return kappa / (2.0 * omega); }
};

struct NonlinearModeBranch {
  int linear_mode = 0;        // 1-based index of the stuck linear mode the branch starts from
  double linear_omega = 0.0;  // its frequency [rad/s]
  Eigen::VectorXd linear_shape;
  std::vector<NonlinearModePoint> points;  // converged points, by increasing amplitude
  bool converged = false;                  // every requested amplitude reached (none skipped)
  std::string failure;                     // where and why it stopped short of the last (with the residual)
  // Requested amplitudes the branch went past without a solution, and why the first one failed.
  std::vector<double> skipped;
  std::string first_skip;
};

// The branch of stuck linear mode `linear_mode` (1-based, ascending frequency of K_stuck, M) at the
// given amplitudes (positive, increasing), each solve continued from the last; a failed step is
// halved in log-amplitude up to options.max_halvings times, then that amplitude is skipped and the
// next tried from the last solution, up to options.max_skips in a row. `static_guess` (n entries, or
// empty) seeds the static part. Throws std::invalid_argument on an invalid model, mode index or
// amplitude list; Newton failures skip amplitudes or end the branch (converged == false; skipped and
// failure say which and where) and never yield a non-finite point.
NonlinearModeBranch trace_nonlinear_mode(const friction::FrictionModel& model, int linear_mode,
                                         const std::vector<double>& amplitudes, const Eigen::VectorXd& static_guess,
                                         const NonlinearModeOptions& options);

}  // namespace bb::hbm
