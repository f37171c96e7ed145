#include "hbm/continuation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "hbm/fixed_frequency.hpp"
#include "linalg/damped_newton.hpp"

// Scaled unknowns y = (x / x_ref, omega / omega_ref); R(y) as in condensed_balance.hpp. Each step:
// tangent t (J_y t = 0, |t| = 1, oriented like the previous one), predictor y_p = y + s t,
// corrector damped Newton on {R(y) = 0, t . (y - y_p) = 0} with backtracking on ||(R / r_ref, g)||.

namespace bb::hbm {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

void validate(const ContinuationOptions& o) {
  if (!(o.omega_start > 0.0) || !(o.omega_end > 0.0) || !std::isfinite(o.omega_start) || !std::isfinite(o.omega_end) ||
      o.omega_start == o.omega_end)
    throw std::invalid_argument("continuation: omega_start and omega_end must be finite, > 0 and distinct");
  if (!(o.min_step > 0.0) || !(o.initial_step >= o.min_step) || !(o.max_step >= o.initial_step) || !(o.grow >= 1.0) ||
      !(o.shrink > 0.0 && o.shrink < 1.0) || o.max_points < 2 || o.max_corrector_iterations < 1)
    throw std::invalid_argument(
        "continuation: need 0 < min_step <= initial_step <= max_step, grow >= 1, 0 < shrink < 1, max_points >= 2, "
        "max_corrector_iterations >= 1");
}

// R and the scaled Jacobian [dR/dx x_ref, dR/domega w_ref] at one y.
struct PathPoint {
  VectorXd residual;
  double norm = std::numeric_limits<double>::infinity();  // ||R|| [N]
  MatrixXd jacobian;                                      // m x (m + 1), scaled columns
  bool ok = false;
};

// The harmonic balance in the scaled variables of the path.
class ScaledPath {
 public:
  ScaledPath(const HarmonicBalance& s, double x_ref, double w_ref)
      : s_(s), m_(s.unknowns()), nc_(static_cast<Index>(s.contact_dofs().size())), x_ref_(x_ref), w_ref_(w_ref) {}

  Index unknowns() const { return m_; }
  void unscale(const VectorXd& y, VectorXd& x, double& w) const {
    x = y.head(m_) * x_ref_;
    w = y[m_] * w_ref_;
  }
  // Max over contact DOFs of the first-harmonic amplitude of x [m].
  double amplitude(const VectorXd& x) const {
    double a = 0.0;
    for (Index i = 0; i < nc_; ++i) a = std::max(a, std::hypot(x[nc_ + i], x[2 * nc_ + i]));
    return a;
  }

  // dR/domega by central differences of the linear part (the contact forces do not depend on omega).
  PathPoint at(const VectorXd& y) const {
    PathPoint a;
    VectorXd x;
    double w = 0.0;
    unscale(y, x, w);
    if (!x.allFinite() || !(w > 0.0)) return a;
    const auto linear = s_.condense(w);
    if (!linear) return a;
    HarmonicBalance::Residual e = s_.residual(*linear, x);
    if (!e.ok) return a;
    a.residual = e.residual;
    a.norm = e.norm;
    a.ok = true;
    const double dw = 1e-6 * w;
    const auto plus = s_.condense(w + dw), minus = s_.condense(w - dw);
    if (!plus || !minus) {
      a.ok = false;
      return a;
    }
    const VectorXd drdw = ((plus->operator_ - minus->operator_) * x - (plus->load - minus->load)) / (2.0 * dw);
    a.jacobian.resize(m_, m_ + 1);
    a.jacobian.leftCols(m_) = (linear->operator_ + e.forces.jacobian) * x_ref_;
    a.jacobian.col(m_) = drdw * w_ref_;
    if (!a.jacobian.allFinite()) a.ok = false;
    return a;
  }

  // Unit t with J t = 0, oriented like `previous`; empty when J has no such direction.
  VectorXd tangent(const MatrixXd& jacobian, const VectorXd& previous) const {
    MatrixXd a(m_ + 1, m_ + 1);
    a.topRows(m_) = jacobian;
    a.row(m_) = previous.transpose();
    VectorXd rhs = VectorXd::Zero(m_ + 1);
    rhs[m_] = 1.0;
    VectorXd t = a.fullPivLu().solve(rhs);
    if (!t.allFinite() || t.norm() == 0.0) return VectorXd();
    t.normalize();
    if (t.dot(previous) < 0.0) t = -t;
    return t;
  }

 private:
  const HarmonicBalance& s_;
  Index m_, nc_;
  double x_ref_, w_ref_;
};

struct Corrected {
  VectorXd y;
  double norm = std::numeric_limits<double>::infinity();  // ||R|| at y [N]
  MatrixXd jacobian;                                      // scaled, m x (m + 1), at y
  int iterations = 0;
  bool converged = false;
};

// Damped Newton on {R(y) = 0, t . (y - y_p) = 0} from y_p: converged when ||R|| meets the solver's
// tolerance and the point lies on the plane to 1e-6 of the step.
Corrected correct(const HarmonicBalance& s, const ScaledPath& path, const VectorXd& predicted, const VectorXd& tangent,
                  double step, int max_iterations) {
  const Index m = path.unknowns();
  const double target = s.residual_tolerance();
  const double r_ref = s.force_scale() > 0.0 ? s.force_scale() : 1.0;
  // The augmented residual (R, g) with g = t . (y - y_p); its data is ||R||.
  const auto augmented = [&](const VectorXd& y) {
    PathPoint a = path.at(y);
    NewtonPoint p;
    p.valid = a.ok;
    p.data = a.norm;
    if (a.residual.size() == m) {
      p.residual.resize(m + 1);
      p.residual.head(m) = a.residual;
      p.residual[m] = tangent.dot(y - predicted);
    }
    if (a.ok) {
      p.jacobian.resize(m + 1, m + 1);
      p.jacobian.topRows(m) = a.jacobian;
      p.jacobian.row(m) = tangent.transpose();
    }
    return p;
  };
  const auto norm_of = [](const NewtonPoint& p) { return std::any_cast<double>(p.data); };
  DampedNewtonOptions options;
  options.tolerance = target;
  options.max_iterations = max_iterations;
  options.max_backtracks = s.options().max_backtracks;
  options.step_solve = NewtonStepSolve::minimum_norm;
  options.merit = [&](const NewtonPoint& p) { return std::hypot(norm_of(p) / r_ref, p.residual[m]); };
  options.converged = [&](const NewtonPoint& p) {
    return norm_of(p) <= target && std::abs(p.residual[m]) <= 1e-6 * step;
  };
  DampedNewtonResult r = damped_newton(augmented, predicted, options);
  Corrected c;
  c.y = std::move(r.x);
  c.norm = norm_of(r.at);
  if (r.at.jacobian.rows() == m + 1) c.jacobian = r.at.jacobian.topRows(m);
  c.iterations = r.iterations;
  c.converged = r.converged;
  return c;
}

// Step length after each corrector: grown after easy ones, shrunk after failures, and where
// shrinking reaches min_step on a kink of the piecewise-smooth R (grazing, stick-slip switch) that
// Newton cannot reach to tolerance from either side, stepped over the kink instead: steps 1, 4, 16,
// 64 times max(last accepted, initial_step), one corrector each, before giving up.
class StepControl {
 public:
  explicit StepControl(const ContinuationOptions& o) : o_(o), step_(o.initial_step), last_good_(o.initial_step) {}
  double step() const { return step_; }
  int jumps() const { return jumps_; }

  // After a failed corrector: false when the continuation must stop (step below min_step).
  bool after_failure() {
    if (jumps_ > 0 || step_ * o_.shrink < o_.min_step) {
      if (jumps_ < 4) {
        ++jumps_;
        step_ = std::min(o_.max_step, std::max(last_good_, o_.initial_step) * std::pow(4.0, jumps_ - 1));
        return true;
      }
      step_ = 0.0;
    }
    return shrink();
  }
  // After a converged corrector that gave no tangent.
  bool shrink() {
    step_ *= o_.shrink;
    return !(step_ < o_.min_step);
  }
  void after_success(int iterations) {
    jumps_ = 0;
    last_good_ = step_;
    if (iterations <= o_.easy_iterations) step_ = std::min(o_.max_step, step_ * o_.grow);
  }

 private:
  const ContinuationOptions& o_;
  double step_, last_good_;
  int jumps_ = 0;
};

// A corner of the path: R is piecewise smooth, and where a contact phase appears (a slip or
// lift-off interval of zero length) the branch can leave the kink at any angle, back in frequency
// too (a non-smooth fold). Beyond a turn of more than 90 degrees no point on the corrector's plane
// normal to the old tangent lies on the new branch, however small the step. The tangent of the
// piece beyond the kink comes from the Jacobian at y + step t; both its orientations are tried,
// and a point is accepted only next to y (within 3 steps) and not back on the piece behind. Only
// once the step has shrunk well below the largest (a hundredth): at longer steps the path's own
// curvature, not a kink, may have failed the corrector, and a turn there could lead back.
struct Turn {
  Corrected corrected;
  VectorXd tangent;
};

std::optional<Turn> turn_at_corner(const HarmonicBalance& s, const ScaledPath& path, const VectorXd& y,
                                   const VectorXd& tangent, double step, int max_iterations, int& iterations) {
  const PathPoint beyond = path.at(y + step * tangent);
  if (!beyond.ok) return std::nullopt;
  const VectorXd piece = path.tangent(beyond.jacobian, tangent);
  if (piece.size() == 0 || piece.dot(tangent) > 0.999) return std::nullopt;  // no corner within the step
  for (const double sign : {-1.0, 1.0}) {
    const VectorXd along = sign * piece;
    Corrected c = correct(s, path, y + step * along, along, step, max_iterations);
    iterations += c.iterations;
    if (!c.converged || (c.y - y).norm() > 3.0 * step) continue;
    VectorXd t = path.tangent(c.jacobian, along);
    if (t.size() == 0 || ((c.y - y).dot(tangent) < 0.0 && std::abs(t.dot(tangent)) > 0.99))
      continue;  // back on the piece the path came along
    return Turn{std::move(c), std::move(t)};
  }
  return std::nullopt;
}

// x_ref of the arclength scaling from the first solution.
double amplitude_scale(const ContinuationOptions& o, const VectorXd& first, Index m, Index nc) {
  double x_ref = o.amplitude_scale;
  if (!(x_ref > 0.0)) x_ref = first.tail(m - nc).norm();
  if (!(x_ref > 0.0)) x_ref = first.norm();
  if (!(x_ref > 0.0)) x_ref = 1.0;
  return x_ref;
}

}  // namespace

ContinuationResult continue_in_frequency(const HarmonicBalance& s, const ContinuationOptions& o) {
  validate(o);
  ContinuationResult result;
  const Index m = s.unknowns();
  const double direction = o.omega_end > o.omega_start ? 1.0 : -1.0;

  const HbmSolution first = solve_at_frequency(s, o.omega_start, o.initial);
  if (!first.converged) {
    result.failure = "first point: " + first.failure;
    return result;
  }
  result.amplitude_scale = amplitude_scale(o, first.x, m, static_cast<Index>(s.contact_dofs().size()));
  const ScaledPath path(s, result.amplitude_scale, o.omega_start);

  VectorXd y(m + 1), tangent;  // the last point of the path and its tangent
  y.head(m) = first.x / result.amplitude_scale;
  y[m] = 1.0;
  {
    const PathPoint at = path.at(y);
    VectorXd seed = VectorXd::Zero(m + 1);
    seed[m] = direction;
    if (at.ok) tangent = path.tangent(at.jacobian, seed);
  }
  if (tangent.size() == 0) {
    result.failure = fmt::format("no tangent at the first point (|R| = {:.3g} N, omega = {:.6g} rad/s)", first.residual,
                                 o.omega_start);
    return result;
  }
  result.points.push_back({o.omega_start, first.x, first.residual, first.iterations, 0.0, tangent[m]});
  if (o.progress) o.progress({0, o.omega_start, path.amplitude(first.x), 0.0, first.iterations});

  StepControl control(o);
  int corner_tries = 0;  // since the last accepted point
  const double w_end_scaled = o.omega_end / o.omega_start;
  const double back_limit = o.omega_back > 0.0 ? o.omega_back / o.omega_start : 0.5 * std::abs(w_end_scaled - 1.0);
  while (true) {
    if (static_cast<int>(result.points.size()) >= o.max_points) {
      result.failure = fmt::format("stopped after {} points at omega = {:.6g} rad/s (|R| = {:.3g} N) before omega_end",
                                   result.points.size(), result.points.back().omega, result.points.back().residual);
      break;
    }
    const double step = control.step();
    Corrected c = correct(s, path, y + step * tangent, tangent, step, o.max_corrector_iterations);
    result.corrector_iterations += c.iterations;
    VectorXd t;
    if (!c.converged) {
      ++result.rejected_steps;
      // Twice per stall at most: the first small steps reach past a kink next to y; more tries
      // cost two correctors each where the stall has another cause.
      std::optional<Turn> turn;
      if (step <= 1e-2 * o.max_step && corner_tries < 2) {
        ++corner_tries;
        turn = turn_at_corner(s, path, y, tangent, step, o.max_corrector_iterations, result.corrector_iterations);
      }
      if (turn) {
        ++result.corners;
        c = std::move(turn->corrected);
        t = std::move(turn->tangent);
      }
    }
    if (!c.converged) {
      if (control.after_failure()) continue;
      result.failure = fmt::format(
          "corrector failed with step below min_step {:.3g} near omega = {:.6g} rad/s (|R| = {:.3g} N, target {:.3g} "
          "N)",
          o.min_step, result.points.back().omega, std::isfinite(c.norm) ? c.norm : -1.0, s.residual_tolerance());
      break;
    }
    if (t.size() == 0) t = path.tangent(c.jacobian, tangent);
    if (t.size() == 0) {
      ++result.rejected_steps;
      if (control.shrink()) continue;
      result.failure = fmt::format("no tangent near omega = {:.6g} rad/s", result.points.back().omega);
      break;
    }
    if (control.jumps() > 0) ++result.jumps;
    if ((t[m] > 0.0) != (tangent[m] > 0.0) && t[m] != 0.0 && tangent[m] != 0.0) ++result.turning_points;
    if (o.max_turning_points > 0 && result.turning_points > o.max_turning_points) {
      result.failure = fmt::format(
          "the path turned back and forth {} times before omega_end (near omega = {:.6g} "
          "rad/s): it wanders along kinks",
          result.turning_points, c.y[m] * o.omega_start);
      break;
    }
    y = c.y;
    tangent = t;
    VectorXd x;
    double w = 0.0;
    path.unscale(y, x, w);
    result.points.push_back({w, x, c.norm, c.iterations, step, t[m]});
    if (o.progress) o.progress({static_cast<int>(result.points.size()) - 1, w, path.amplitude(x), step, c.iterations});
    if (direction * (y[m] - w_end_scaled) >= 0.0) {
      result.converged = true;
      break;
    }
    if (direction * (y[m] - 1.0) < -back_limit) {
      result.turned_back = true;
      result.failure =
          fmt::format("the path turned back past omega_start (omega = {:.6g} rad/s, |R| = {:.3g} N)", w, c.norm);
      break;
    }
    control.after_success(c.iterations);
    corner_tries = 0;
  }
  return result;
}

}  // namespace bb::hbm
