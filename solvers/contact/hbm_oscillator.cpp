#include "contact/hbm_oscillator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace bb::contact {

double HbmSolution::first_harmonic_amplitude() const { return x.size() >= 3 ? std::hypot(x[1], x[2]) : 0.0; }

namespace {

// A(omega) of the linear part with stiffness k, block-diagonal in the real harmonic layout.
Eigen::MatrixXd dynamic_stiffness(const FrictionOscillator& o, double stiffness, double omega, int harmonics) {
  const Eigen::Index m = harmonic_size(harmonics);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
  a(0, 0) = stiffness;
  for (int h = 1; h <= harmonics; ++h) {
    const Eigen::Index i = 2 * h - 1;
    const double diagonal = stiffness - o.mass * h * h * omega * omega, cross = o.damping * h * omega;
    a(i, i) = a(i + 1, i + 1) = diagonal;
    a(i, i + 1) = cross;
    a(i + 1, i) = -cross;
  }
  return a;
}

struct Evaluation {
  Eigen::VectorXd residual;
  double norm = 0.0;
  AftResult contact;
};

}  // namespace

HbmSolution solve_friction_oscillator(const FrictionOscillator& o, double omega, const HbmOptions& options,
                                      const std::optional<Eigen::VectorXd>& initial) {
  validate(o.contact);
  if (!(o.mass > 0.0) || !std::isfinite(o.mass)) throw std::invalid_argument("friction oscillator: mass must be finite and > 0");
  if (!(o.damping >= 0.0) || !std::isfinite(o.damping))
    throw std::invalid_argument("friction oscillator: damping must be finite and >= 0");
  if (!(o.stiffness >= 0.0) || !std::isfinite(o.stiffness))
    throw std::invalid_argument("friction oscillator: stiffness must be finite and >= 0");
  if (!std::isfinite(o.force)) throw std::invalid_argument("friction oscillator: force must be finite");
  if (!(omega > 0.0) || !std::isfinite(omega)) throw std::invalid_argument("friction oscillator: omega must be finite and > 0");
  if (options.harmonics < 1) throw std::invalid_argument("friction oscillator: at least one harmonic");
  if (options.max_iterations < 1 || options.max_backtracks < 0 || !(options.tolerance > 0.0))
    throw std::invalid_argument("friction oscillator: max_iterations >= 1, max_backtracks >= 0 and tolerance > 0");

  const int harmonics = options.harmonics;
  const Eigen::Index m = harmonic_size(harmonics);
  AftOptions aft = options.aft;
  if (aft.samples == 0) aft.samples = std::max(64, 16 * (2 * harmonics + 1));
  const Eigen::VectorXd no_normal_motion = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd excitation = Eigen::VectorXd::Zero(m);
  excitation[1] = o.force;
  const Eigen::MatrixXd linear = dynamic_stiffness(o, o.stiffness, omega, harmonics);

  const auto evaluate = [&](const Eigen::VectorXd& x) {
    Evaluation e{.residual = {}, .norm = 0.0, .contact = aft_jenkins(o.contact, x, no_normal_motion, aft)};
    e.residual = linear * x + e.contact.tangential - excitation;
    e.norm = e.residual.norm();
    return e;
  };

  Eigen::VectorXd x;
  if (initial) {
    if (initial->size() != m)
      throw std::invalid_argument(fmt::format("friction oscillator: initial guess has {} coefficients, expected {}",
                                              initial->size(), m));
    x = *initial;
  } else {
    // The two linear limits; near the stuck resonance the free one is the better start and vice versa.
    const Eigen::VectorXd stuck =
        dynamic_stiffness(o, o.stiffness + o.contact.kt, omega, harmonics).fullPivLu().solve(excitation);
    const Eigen::VectorXd sliding = linear.fullPivLu().solve(excitation);
    const bool sliding_ok = sliding.allFinite(), stuck_ok = stuck.allFinite();
    if (sliding_ok && stuck_ok) x = evaluate(sliding).norm < evaluate(stuck).norm ? sliding : stuck;
    else x = stuck_ok ? stuck : (sliding_ok ? sliding : Eigen::VectorXd::Zero(m));
  }

  HbmSolution s;
  const double target = options.tolerance * (std::abs(o.force) + o.contact.mu * o.contact.n0);
  Evaluation current = evaluate(x);
  for (int iteration = 0;; ++iteration) {
    s.iterations = iteration;
    if (!current.contact.closed) {
      s.failure = fmt::format("the contact loop did not close in {} periods", current.contact.periods);
      break;
    }
    if (current.norm <= target) {
      s.converged = true;
      break;
    }
    if (iteration == options.max_iterations) {
      s.failure = fmt::format("no convergence in {} Newton iterations (|R| = {:.3g} N, target {:.3g} N)", iteration,
                              current.norm, target);
      break;
    }
    const Eigen::MatrixXd jacobian = linear + current.contact.dtangential_du;
    const Eigen::VectorXd step = jacobian.fullPivLu().solve(-current.residual);
    if (!step.allFinite()) {
      s.failure = "singular harmonic-balance Jacobian";
      break;
    }
    // Backtracking (Armijo on ||R||): the map is only piecewise linear, a full Newton step can
    // cross stick/slip switches and land further from the solution than it started.
    double alpha = 1.0;
    bool accepted = false;
    for (int b = 0; b <= options.max_backtracks; ++b, alpha *= 0.5) {
      Evaluation trial = evaluate(x + alpha * step);
      if (trial.norm <= (1.0 - 1e-4 * alpha) * current.norm) {
        x += alpha * step;
        current = std::move(trial);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      s.iterations = iteration + 1;
      s.failure = fmt::format("line search failed after {} halvings (|R| = {:.3g} N)", options.max_backtracks,
                              current.norm);
      break;
    }
  }
  s.x = x;
  s.residual = current.norm;
  s.contact = std::move(current.contact);
  return s;
}

}  // namespace bb::contact
