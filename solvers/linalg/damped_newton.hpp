// Damped Newton's method for R(x) = 0: the one Newton loop of the nonlinear solvers (harmonic
// balance at fixed frequency and its continuation corrector, the Newmark step, the static initial
// state). Units: those of the caller's x and R.
//
// Each iteration solves J dx = -R, then backtracks x + a dx, a = 1, 1/2, 1/4, ..., until the merit
// (||R|| unless the caller gives its own) drops by the Armijo factor (1 - armijo a) (Nocedal &
// Wright, Numerical Optimization, 2nd ed., section 3.1). Our residuals are only piecewise smooth
// (stick/slip and contact/lift-off switches): a full step can cross a switch and land further from
// the solution than it started, which backtracking catches. Where backtracking fails because the
// exact Jacobian points across a kink, the secant (Broyden) step, whose Jacobian is corrected by
// the residual at the full step beyond the kink, is backtracked next; then, optionally,
// Levenberg-Marquardt steps (Nocedal & Wright section 10.3) along a blend of the Newton and
// steepest-descent directions.
//
// With a ChordFactorization the iteration first tries the chord (simplified Newton) step: the LU of
// the last Jacobian it factorized, kept across solves, applied to the new residual. The step is
// taken when it shrinks the merit by the factorization's contraction factor; otherwise the
// Jacobian at x is factorized afresh. Along a sweep the Jacobian changes little from one frequency
// to the next, so most steps cost a residual and a triangular solve instead of an LU (Deuflhard,
// Newton Methods for Nonlinear Problems, 2004, section 2.1.4).
//
// Contract: never throws on non-convergence (converged == false, a status and a message with |R|),
// never returns a non-finite x or residual.
#pragma once
#include <Eigen/Dense>

#include <any>
#include <functional>
#include <string>

#include "linalg/dense_lu.hpp"

namespace bb {

// What the caller's system returns at one x.
struct NewtonPoint {
  Eigen::VectorXd residual;  // R(x)
  Eigen::MatrixXd jacobian;  // dR/dx, residual.size() rows, x.size() columns (may be left empty when !valid)
  // false: R cannot be used at x (e.g. a slider loop that did not close); such a point is never
  // accepted, and a start point that is not valid ends the iteration at once.
  bool valid = true;
  std::any data;  // anything computed with R (e.g. the contact time histories), handed back with the final point
  // When set, the system left `jacobian` empty and this fills it from the point (its data): a trial
  // point the line search rejects, or one a chord step leaves, never needs its Jacobian. Called
  // before a step is solved at the point and on the point the iteration returns.
  std::function<void(NewtonPoint&)> complete_jacobian = {};
};

using NewtonSystem = std::function<NewtonPoint(const Eigen::VectorXd& x)>;

// How J dx = -R is solved.
enum class NewtonStepSolve {
  // The minimum-norm step, which puts no component along a null space of J (a direction that
  // leaves R unchanged) where a pivoted LU would put an arbitrary one: by partial-pivot LU where J
  // is square and its estimated reciprocal condition number exceeds 1e-10 (no null space), else
  // by complete orthogonal decomposition (rank threshold 1e-13).
  minimum_norm,
  partial_pivot_lu,  // fastest; J assumed invertible (a singular J gives a non-finite step)
  full_pivot_lu,     // rank-revealing: J not invertible stops the iteration as singular
};

// The factorized Jacobian a sweep carries from one solve to the next (one per thread of solves).
class ChordFactorization {
 public:
  // A chord step counts when it shrinks the merit by at least this factor (in (0, 1)); a slower
  // contraction costs more residuals than the factorization it saves.
  explicit ChordFactorization(double contraction = 0.5);
  double contraction() const { return contraction_; }
  bool fits(Eigen::Index size) const { return held_ && lu_.rows() == size; }
  void hold(DenseLU lu);
  void drop() { held_ = false; }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const { return lu_.solve(rhs); }
  long chord_steps = 0;     // chord steps taken
  long factorizations = 0;  // Jacobians factorized into it

 private:
  double contraction_;
  bool held_ = false;
  DenseLU lu_;
};

struct DampedNewtonOptions {
  // Converged when merit <= tolerance (units of R) unless `converged` is given. 0 asks for R = 0.
  double tolerance = 0.0;
  int max_iterations = 50;  // accepted Newton steps before the iteration stops as not converged
  int max_backtracks = 30;  // halvings of a step (max_backtracks + 1 trials) before the line search fails
  double armijo = 1e-4;     // sufficient-decrease constant of the backtracking test
  NewtonStepSolve step_solve = NewtonStepSolve::minimum_norm;
  // After a failed line search, try Levenberg-Marquardt steps (J^T J + lambda s I) dx = -J^T R,
  // s = max diag(J^T J), lambda = 1e-8, 1e-7, ..., 1e2, the first that lowers the merit accepted.
  bool levenberg_marquardt = false;
  // The merit that backtracking reduces and the tolerance tests; empty: ||R||. It is evaluated
  // only at valid points.
  std::function<double(const NewtonPoint&)> merit = {};
  // The convergence test at a valid point; empty: merit <= tolerance.
  std::function<bool(const NewtonPoint&)> converged = {};
  // Chord steps from this factorization (see above); null: a Newton step at every iteration. Used
  // with step_solve minimum_norm only (the LU of a well-conditioned square Jacobian is kept).
  ChordFactorization* chord = nullptr;
  // Whether the returned point carries its Jacobian (false: a deferred one is left to the caller).
  bool jacobian_at_solution = true;
};

enum class NewtonStatus {
  converged,
  invalid_point,       // the start point was not valid, or its merit not finite
  iteration_limit,     // max_iterations steps accepted without convergence
  singular_jacobian,   // the step solve failed (non-finite step, or J not invertible for full_pivot_lu)
  line_search_failed,  // no trial step (nor Levenberg-Marquardt step, when enabled) reduced the merit
};

struct DampedNewtonResult {
  Eigen::VectorXd x;  // the last accepted iterate (the start when none was), always finite
  NewtonPoint at;     // the system at x (its data included)
  // Merit at x (||R|| unless the caller gave its own); +inf when x was not a valid point.
  double residual = 0.0;
  // Newton steps accepted (a Levenberg-Marquardt step counts as one); an attempt that failed
  // (line search, singular step) is not counted: callers that report it add one.
  int iterations = 0;
  bool converged = false;
  NewtonStatus status = NewtonStatus::invalid_point;
  std::string failure;  // empty when converged, else what stopped the iteration and |R|
};

// From x0. `system` is called once per trial point (and once at x0).
[[nodiscard]] DampedNewtonResult damped_newton(const NewtonSystem& system, Eigen::VectorXd x0,
                                               const DampedNewtonOptions& options);
// From x0 already evaluated (`at_x0` = system(x0)), for callers that compare several starts.
[[nodiscard]] DampedNewtonResult damped_newton(const NewtonSystem& system, Eigen::VectorXd x0, NewtonPoint at_x0,
                                               const DampedNewtonOptions& options);

}  // namespace bb
