#include "linalg/damped_newton.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <utility>

namespace bb {

namespace {

// Solves J dx = -R the way the options ask; false when the step cannot be used.
bool newton_step(const NewtonPoint& at, NewtonStepSolve how, Eigen::VectorXd& step) {
  switch (how) {
    case NewtonStepSolve::minimum_norm: {
      // A well-conditioned J has no null space, so its LU step is the minimum-norm step, at a
      // fraction of the decomposition's cost (on Table XI at H = 7 the decomposition took a quarter
      // of the sweeps' time).
      if (at.jacobian.rows() == at.jacobian.cols()) {
        const Eigen::PartialPivLU<Eigen::MatrixXd> lu(at.jacobian);
        if (lu.rcond() > 1e-10) {
          step = lu.solve(-at.residual);
          if (step.allFinite()) break;
        }
      }
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
      cod.setThreshold(1e-13);
      cod.compute(at.jacobian);
      step = cod.solve(-at.residual);
      break;
    }
    case NewtonStepSolve::partial_pivot_lu:
      step = at.jacobian.partialPivLu().solve(-at.residual);
      break;
    case NewtonStepSolve::full_pivot_lu: {
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(at.jacobian);
      if (!lu.isInvertible()) return false;
      step = lu.solve(-at.residual);
      break;
    }
  }
  return step.allFinite();
}

class Iteration {
 public:
  Iteration(const NewtonSystem& system, const DampedNewtonOptions& options) : system_(system), options_(options) {}

  double merit(const NewtonPoint& p) const {
    if (!p.valid) return std::numeric_limits<double>::infinity();
    return options_.merit ? options_.merit(p) : p.residual.norm();
  }
  bool converged(const NewtonPoint& p, double merit_at_p) const {
    return options_.converged ? options_.converged(p) : merit_at_p <= options_.tolerance;
  }

  // Backtracking along `step` from (x, at): the first a = 2^-b with merit(x + a step) <= (1 - armijo a) merit.
  bool backtrack(Eigen::VectorXd& x, NewtonPoint& at, double& merit_at, const Eigen::VectorXd& step) const {
    double alpha = 1.0;
    for (int b = 0; b <= options_.max_backtracks; ++b, alpha *= 0.5) {
      Eigen::VectorXd trial_x = x + alpha * step;
      NewtonPoint trial = system_(trial_x);
      const double m = merit(trial);
      if (trial.valid && std::isfinite(m) && m <= (1.0 - options_.armijo * alpha) * merit_at) {
        x = std::move(trial_x);
        at = std::move(trial);
        merit_at = m;
        return true;
      }
    }
    return false;
  }

  // Levenberg-Marquardt steps of growing damping; the first that lowers the merit at all is taken.
  bool levenberg_marquardt(Eigen::VectorXd& x, NewtonPoint& at, double& merit_at) const {
    const Eigen::MatrixXd normal = at.jacobian.transpose() * at.jacobian;
    const Eigen::VectorXd gradient = at.jacobian.transpose() * at.residual;
    const double scale = normal.diagonal().maxCoeff();
    for (double lambda = 1e-8; lambda <= 1e2 && scale > 0.0; lambda *= 10.0) {
      Eigen::MatrixXd damped = normal;
      damped.diagonal().array() += lambda * scale;
      const Eigen::VectorXd step = damped.ldlt().solve(-gradient);
      if (!step.allFinite()) continue;
      Eigen::VectorXd trial_x = x + step;
      NewtonPoint trial = system_(trial_x);
      const double m = merit(trial);
      if (trial.valid && m < merit_at) {
        x = std::move(trial_x);
        at = std::move(trial);
        merit_at = m;
        return true;
      }
    }
    return false;
  }

 private:
  const NewtonSystem& system_;
  const DampedNewtonOptions& options_;
};

}  // namespace

DampedNewtonResult damped_newton(const NewtonSystem& system, Eigen::VectorXd x0, const DampedNewtonOptions& options) {
  NewtonPoint at = system(x0);
  return damped_newton(system, std::move(x0), std::move(at), options);
}

DampedNewtonResult damped_newton(const NewtonSystem& system, Eigen::VectorXd x0, NewtonPoint at_x0,
                                 const DampedNewtonOptions& options) {
  const Iteration iteration(system, options);
  DampedNewtonResult out;
  out.x = std::move(x0);
  out.at = std::move(at_x0);
  double merit = iteration.merit(out.at);
  const auto stop = [&](NewtonStatus status, const char* what) {
    out.status = status;
    out.failure = fmt::format("{} after {} Newton iterations (|R| = {:.3g}, tolerance {:.3g})", what, out.iterations,
                              merit, options.tolerance);
  };
  while (true) {
    if (!out.at.valid || !std::isfinite(merit) || !out.x.allFinite()) {
      stop(NewtonStatus::invalid_point, "R could not be evaluated at the start");
      break;
    }
    if (iteration.converged(out.at, merit)) {
      out.converged = true;
      out.status = NewtonStatus::converged;
      break;
    }
    if (out.iterations >= options.max_iterations) {
      stop(NewtonStatus::iteration_limit, "no convergence");
      break;
    }
    Eigen::VectorXd step;
    if (!newton_step(out.at, options.step_solve, step)) {
      stop(NewtonStatus::singular_jacobian, "singular Jacobian");
      break;
    }
    if (!iteration.backtrack(out.x, out.at, merit, step) &&
        !(options.levenberg_marquardt && iteration.levenberg_marquardt(out.x, out.at, merit))) {
      stop(NewtonStatus::line_search_failed, "line search failed");
      break;
    }
    ++out.iterations;
  }
  out.residual = std::isfinite(merit) ? merit : std::numeric_limits<double>::infinity();
  if (!out.x.allFinite()) out.x.setZero();  // never hand a non-finite iterate to a caller
  return out;
}

}  // namespace bb
