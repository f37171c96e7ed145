#include "hbm/fixed_frequency.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "linalg/damped_newton.hpp"

namespace bb::hbm {

namespace {

// R and (as data) the AFT of every contact at x; its Jacobian L + dg/dx assembled when the
// iteration asks (a rejected trial point does not: on Table XI about a third of the evaluations).
NewtonPoint balance_at(const HarmonicBalance& s, const HarmonicBalance::Linear& linear, const Eigen::VectorXd& x) {
  HarmonicBalance::Residual r = s.residual(linear, x, false);
  NewtonPoint p;
  p.valid = r.ok;
  p.residual = std::move(r.residual);
  p.data = std::move(r.forces.contacts);
  p.complete_jacobian = [&s, &linear](NewtonPoint& q) {
    q.jacobian = linear.operator_ + s.contact_jacobian(std::any_cast<const std::vector<friction::AftResult>&>(q.data));
  };
  return p;
}

double norm_of(const NewtonPoint& p) { return p.valid ? p.residual.norm() : std::numeric_limits<double>::infinity(); }

// One damped Newton solve from x (evaluated: `at`), its result in the solver's terms.
HbmSolution newton(const HarmonicBalance& s, const HarmonicBalance::Linear& linear, double omega, Eigen::VectorXd x,
                   NewtonPoint at, ChordFactorization* chord) {
  const double target = s.residual_tolerance();
  const DampedNewtonOptions options{.tolerance = target,
                                    .max_iterations = s.options().max_iterations,
                                    .max_backtracks = s.options().max_backtracks,
                                    .step_solve = NewtonStepSolve::minimum_norm,
                                    .levenberg_marquardt = true,
                                    .chord = chord,
                                    .jacobian_at_solution = false};
  DampedNewtonResult r = damped_newton([&](const Eigen::VectorXd& y) { return balance_at(s, linear, y); }, std::move(x),
                                       std::move(at), options);
  HbmSolution out;
  out.omega = omega;
  out.x = std::move(r.x);
  out.converged = r.converged;
  // A failed line search counts the attempt as an iteration, a singular Jacobian does not.
  out.iterations = r.iterations + (r.status == NewtonStatus::line_search_failed ? 1 : 0);
  out.residual = std::isfinite(r.residual) ? r.residual : std::numeric_limits<double>::max();
  switch (r.status) {
    case NewtonStatus::converged:
      break;
    case NewtonStatus::invalid_point:
      out.failure = fmt::format(
          "contact evaluation failed (non-finite or slider loop not closed) at omega = {:.6g} rad/s", omega);
      break;
    case NewtonStatus::iteration_limit:
      out.failure = fmt::format(
          "no convergence in {} Newton iterations (|R| = {:.3g} N, target {:.3g} N) at omega = "
          "{:.6g} rad/s",
          r.iterations, r.residual, target, omega);
      break;
    case NewtonStatus::singular_jacobian:
      out.failure = fmt::format("singular Jacobian (|R| = {:.3g} N) at omega = {:.6g} rad/s", r.residual, omega);
      break;
    case NewtonStatus::line_search_failed:
      out.failure = fmt::format(
          "line search failed after {} halvings (|R| = {:.3g} N, target {:.3g} N) at omega = "
          "{:.6g} rad/s",
          s.options().max_backtracks, r.residual, target, omega);
      break;
  }
  if (auto* contacts = std::any_cast<std::vector<friction::AftResult>>(&r.at.data)) out.contacts = std::move(*contacts);
  return out;
}

HbmSolution singular_at(const HarmonicBalance& s, double omega) {
  HbmSolution out;
  out.omega = omega;
  out.residual = std::numeric_limits<double>::max();
  out.x = Eigen::VectorXd::Zero(s.unknowns());
  out.failure = fmt::format("singular dynamic stiffness of the non-contact DOFs at omega = {:.6g} rad/s", omega);
  return out;
}

void check_frequency(double omega) {
  if (!(omega > 0.0) || !std::isfinite(omega))
    throw std::invalid_argument("harmonic balance: omega must be finite and > 0");
}

void check_size(const HarmonicBalance& s, const Eigen::VectorXd& x) {
  if (x.size() != s.unknowns())
    throw std::invalid_argument(
        fmt::format("harmonic balance: initial guess has {} entries, expected {}", x.size(), s.unknowns()));
}

}  // namespace

HbmSolution solve_from(const HarmonicBalance& s, double omega, const Eigen::VectorXd& start,
                       ChordFactorization* chord) {
  check_frequency(omega);
  check_size(s, start);
  const auto linear = s.condense(omega);
  if (!linear) return singular_at(s, omega);
  return newton(s, *linear, omega, start, balance_at(s, *linear, start), chord);
}

HbmSolution solve_at_frequency(const HarmonicBalance& s, double omega, const std::optional<Eigen::VectorXd>& initial,
                               ChordFactorization* chord) {
  check_frequency(omega);
  const auto linear = s.condense(omega);
  if (!linear) return singular_at(s, omega);
  // Starts, in order: the caller's guess, then the two linear limits (contacts stuck: small
  // amplitude; normal springs only: large amplitude), the better one first. Newton on this
  // piecewise-smooth map can stall on a kink from one start and converge from another; each start
  // gets max_iterations, so a solve costs at most three times that.
  HbmSolution best;
  int iterations = 0;
  const auto attempt = [&](Eigen::VectorXd x, NewtonPoint at, HbmStart from) {
    HbmSolution trial = newton(s, *linear, omega, std::move(x), std::move(at), chord);
    trial.start = from;
    iterations += trial.iterations;
    const bool converged = trial.converged;
    if (converged || best.x.size() == 0 || trial.residual < best.residual) best = std::move(trial);
    best.iterations = iterations;
    return converged;
  };
  if (initial) {
    check_size(s, *initial);
    if (attempt(*initial, balance_at(s, *linear, *initial), HbmStart::initial)) return best;
  }
  // The linear limits only when needed: on a sweep the caller's guess almost always converges.
  struct Start {
    Eigen::VectorXd x;
    NewtonPoint at;
    double norm;
    HbmStart from;
  };
  std::vector<Start> limits;
  for (const bool stuck : {true, false}) {
    const auto guess = s.linearized(omega, stuck);
    if (!guess) continue;
    NewtonPoint at = balance_at(s, *linear, *guess);
    const double norm = norm_of(at);
    if (at.valid) limits.push_back({*guess, std::move(at), norm, stuck ? HbmStart::stuck : HbmStart::sliding});
  }
  std::sort(limits.begin(), limits.end(), [](const Start& a, const Start& b) { return a.norm < b.norm; });
  if (limits.empty() && !initial) {
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.unknowns());
    NewtonPoint at = balance_at(s, *linear, zero);
    const double norm = norm_of(at);
    limits.push_back({zero, std::move(at), norm, HbmStart::zero});
  }
  for (Start& start : limits)
    if (attempt(std::move(start.x), std::move(start.at), start.from)) return best;
  return best;
}

}  // namespace bb::hbm
