#include "linalg/damped_newton.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

namespace bb {

namespace {

// The decomposition of J a Newton step was solved with, kept for a second right-hand side.
using StepDecomposition = std::variant<std::monostate, DenseLU, Eigen::FullPivLU<Eigen::MatrixXd>,
                                       Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>>;

Eigen::VectorXd solve_with(const StepDecomposition& d, const Eigen::VectorXd& rhs) {
  return std::visit(
      [&](const auto& dec) -> Eigen::VectorXd {
        if constexpr (std::is_same_v<std::decay_t<decltype(dec)>, std::monostate>)
          return Eigen::VectorXd::Constant(rhs.size(), std::numeric_limits<double>::quiet_NaN());
        else
          return dec.solve(rhs);
      },
      d);
}

// Solves J dx = -R the way the options ask, keeping the decomposition in `d`; false when the
// step cannot be used.
bool newton_step(const NewtonPoint& at, NewtonStepSolve how, Eigen::VectorXd& step, StepDecomposition& d) {
  switch (how) {
    case NewtonStepSolve::minimum_norm: {
      // A well-conditioned J has no null space, so its LU step is the minimum-norm step, at a
      // fraction of the decomposition's cost (on Table XI at H = 7 the decomposition took a quarter
      // of the sweeps' time).
      if (at.jacobian.rows() == at.jacobian.cols()) {
        DenseLU lu(at.jacobian);
        if (lu.rcond() > 1e-10) {
          step = lu.solve(-at.residual);
          d = std::move(lu);
          if (step.allFinite()) break;
        }
      }
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
      cod.setThreshold(1e-13);
      cod.compute(at.jacobian);
      step = cod.solve(-at.residual);
      d = std::move(cod);
      break;
    }
    case NewtonStepSolve::partial_pivot_lu: {
      DenseLU lu(at.jacobian);
      step = lu.solve(-at.residual);
      d = std::move(lu);
      break;
    }
    case NewtonStepSolve::full_pivot_lu: {
      Eigen::FullPivLU<Eigen::MatrixXd> lu(at.jacobian);
      if (!lu.isInvertible()) return false;
      step = lu.solve(-at.residual);
      d = std::move(lu);
      break;
    }
  }
  return step.allFinite();
}

// The point's Jacobian, from its system's deferred assembly where there is one.
void complete(NewtonPoint& p) {
  if (!p.complete_jacobian || !p.valid) return;
  const auto fill = std::move(p.complete_jacobian);
  p.complete_jacobian = {};
  fill(p);
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

  // Evaluates x + step and moves there when that point is valid and `accepts` its finite merit.
  // `residual` (when given) receives R there where the point is valid.
  template <class Accepts>
  bool move_if(Eigen::VectorXd& x, NewtonPoint& at, double& merit_at, const Eigen::VectorXd& step, Accepts accepts,
               Eigen::VectorXd* residual = nullptr) const {
    Eigen::VectorXd trial_x = x + step;
    NewtonPoint trial = system_(trial_x);
    const double m = merit(trial);
    if (residual && trial.valid && trial.residual.allFinite()) *residual = trial.residual;
    if (!(trial.valid && std::isfinite(m) && accepts(m))) return false;
    x = std::move(trial_x);
    at = std::move(trial);
    merit_at = m;
    return true;
  }

  // Backtracking along `step` from (x, at): the first a = 2^-b with merit(x + a step) <= (1 - armijo a) merit.
  // `full` (when given) receives R at the full step where that point is valid, else stays empty.
  bool backtrack(Eigen::VectorXd& x, NewtonPoint& at, double& merit_at, const Eigen::VectorXd& step,
                 Eigen::VectorXd* full = nullptr) const {
    double alpha = 1.0;
    for (int b = 0; b <= options_.max_backtracks; ++b, alpha *= 0.5) {
      const double bound = (1.0 - options_.armijo * alpha) * merit_at;
      if (move_if(
              x, at, merit_at, alpha * step, [bound](double m) { return m <= bound; }, b == 0 ? full : nullptr))
        return true;
    }
    return false;
  }

  // After a blocked line search: the step of the Broyden (secant) update J + R_1 dx^T / (dx . dx)
  // of the Jacobian, R_1 the residual at the full step, which sees the kink the step crossed where
  // J does not; solved on J's decomposition by the Sherman-Morrison formula (Dennis & Schnabel,
  // Numerical Methods for Unconstrained Optimization and Nonlinear Equations, 1996, section 8.1).
  bool secant_step(Eigen::VectorXd& x, NewtonPoint& at, double& merit_at, const Eigen::VectorXd& dx,
                   const Eigen::VectorXd& full, const StepDecomposition& d) const {
    if (full.size() != dx.size()) return false;
    const Eigen::VectorXd z = solve_with(d, full);
    const double dd = dx.squaredNorm(), denominator = dd + dx.dot(z);
    if (!z.allFinite() || !(std::abs(denominator) > 1e-12 * dd)) return false;
    const Eigen::VectorXd step = dx - (dd / denominator) * z;
    if (!step.allFinite()) return false;
    return backtrack(x, at, merit_at, step);
  }

  // The chord step from the held factorization, taken when it contracts the merit enough.
  bool chord_step(Eigen::VectorXd& x, NewtonPoint& at, double& merit_at) const {
    ChordFactorization* chord = options_.chord;
    if (!chord || !chord->fits(x.size()) || at.residual.size() != x.size()) return false;
    const Eigen::VectorXd step = chord->solve(-at.residual);
    const double bound = chord->contraction() * merit_at;
    if (!step.allFinite() || !move_if(x, at, merit_at, step, [bound](double m) { return m <= bound; })) return false;
    ++chord->chord_steps;
    return true;
  }

  // Levenberg-Marquardt steps of growing damping; the first that lowers the merit at all is taken.
  bool levenberg_marquardt(Eigen::VectorXd& x, NewtonPoint& at, double& merit_at) const {
    complete(at);
    const Eigen::MatrixXd normal = at.jacobian.transpose() * at.jacobian;
    const Eigen::VectorXd gradient = at.jacobian.transpose() * at.residual;
    const double scale = normal.diagonal().maxCoeff();
    for (double lambda = 1e-8; lambda <= 1e2 && scale > 0.0; lambda *= 10.0) {
      Eigen::MatrixXd damped = normal;
      damped.diagonal().array() += lambda * scale;
      const Eigen::VectorXd step = damped.ldlt().solve(-gradient);
      const double bound = merit_at;
      if (step.allFinite() && move_if(x, at, merit_at, step, [bound](double m) { return m < bound; })) return true;
    }
    return false;
  }

 private:
  const NewtonSystem& system_;
  const DampedNewtonOptions& options_;
};

}  // namespace

ChordFactorization::ChordFactorization(double contraction) : contraction_(contraction) {
  if (!(contraction > 0.0 && contraction < 1.0))
    throw std::invalid_argument(fmt::format("chord contraction must lie in (0, 1), got {}", contraction));
}

void ChordFactorization::hold(DenseLU lu) {
  lu_ = std::move(lu);
  held_ = true;
  ++factorizations;
}

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
    if (iteration.chord_step(out.x, out.at, merit)) {
      ++out.iterations;
      continue;
    }
    Eigen::VectorXd step, full;
    StepDecomposition decomposition;
    complete(out.at);
    if (!newton_step(out.at, options.step_solve, step, decomposition)) {
      stop(NewtonStatus::singular_jacobian, "singular Jacobian");
      break;
    }
    const bool moved = iteration.backtrack(out.x, out.at, merit, step, &full) ||
                       iteration.secant_step(out.x, out.at, merit, step, full, decomposition) ||
                       (options.levenberg_marquardt && iteration.levenberg_marquardt(out.x, out.at, merit));
    if (options.chord) {
      auto* lu = std::get_if<DenseLU>(&decomposition);
      if (lu && options.step_solve == NewtonStepSolve::minimum_norm)
        options.chord->hold(std::move(*lu));
      else
        options.chord->drop();
    }
    if (!moved) {
      stop(NewtonStatus::line_search_failed, "line search failed");
      break;
    }
    ++out.iterations;
  }
  if (options.jacobian_at_solution) complete(out.at);
  out.residual = std::isfinite(merit) ? merit : std::numeric_limits<double>::infinity();
  if (!out.x.allFinite()) out.x.setZero();  // never hand a non-finite iterate to a caller
  return out;
}

}  // namespace bb
