#include "hbm/response_control.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <vector>

#include "linalg/damped_newton.hpp"

namespace bb::hbm {
namespace {

using Eigen::Index;
using Complex = std::complex<double>;

// The held DOF's first harmonic (a_1, b_1) as P [x; Re F; Im F]: two rows, affine in x's first
// harmonic and in F (harmonic 1 is recovered from harmonic 1 alone).
Eigen::MatrixXd response_rows(const HarmonicBalance& s, double omega, Index dof) {
  const Index nc = static_cast<Index>(s.contact_dofs().size()), n = s.unknowns();
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(2, n + 2);
  const auto& dofs = s.contact_dofs();
  if (const auto it = std::find(dofs.begin(), dofs.end(), dof); it != dofs.end()) {
    const Index i = it - dofs.begin();
    p(0, nc + i) = 1.0;
    p(1, 2 * nc + i) = 1.0;
    return p;
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  const Eigen::MatrixXd q0 = s.recover(zero, omega);  // the unit force alone
  const double sa = q0(dof, 1), sb = q0(dof, 2);
  // Z = a - i b scales with F: F = 1 gives (sa, sb); F = i gives i (sa - i sb) = sb + i sa.
  p.col(n) << sa, sb;
  p.col(n + 1) << sb, -sa;
  for (Index slot = nc; slot < 3 * nc; ++slot) {
    Eigen::VectorXd e = zero;
    e[slot] = 1.0;
    const Eigen::MatrixXd q = s.recover(e, omega);
    p.col(slot) << q(dof, 1) - sa, q(dof, 2) - sb;
  }
  return p;
}

// The linear limit scaled so that the held DOF has the asked amplitude at phase 0.
std::optional<ControlledStart> linear_start(const HarmonicBalance& s, const Eigen::MatrixXd& p, double omega,
                                            const ControlledResponse& c, bool stuck) {
  const std::optional<Eigen::VectorXd> lin = s.linearized(omega, stuck);
  if (!lin) return std::nullopt;
  const Index nc = static_cast<Index>(s.contact_dofs().size()), n = s.unknowns();
  const Eigen::Vector2d ab = p.leftCols(n) * *lin + p.col(n);  // at F = 1
  const Complex z(ab[0], -ab[1]);
  if (!(std::abs(z) > 0.0) || !std::isfinite(std::abs(z))) return std::nullopt;
  const Complex f = c.amplitude / z;
  ControlledStart start{*lin, f};
  for (Index i = 0; i < nc; ++i) {
    const Complex zi = Complex((*lin)[nc + i], -(*lin)[2 * nc + i]) * f;
    start.x[nc + i] = zi.real();
    start.x[2 * nc + i] = -zi.imag();
  }
  return start;
}

}  // namespace

ControlledSolution solve_controlled(const HarmonicBalance& s, double omega, const ControlledResponse& c,
                                    const std::optional<ControlledStart>& initial) {
  ControlledSolution out;
  out.solution.omega = omega;
  out.solution.residual = std::numeric_limits<double>::max();
  const std::optional<HarmonicBalance::Linear> linear = s.condense(omega);
  if (!linear || !(c.amplitude > 0.0)) {
    out.solution.failure = fmt::format("singular linear part at omega = {:.6g} rad/s", omega);
    return out;
  }
  const Index nc = static_cast<Index>(s.contact_dofs().size()), n = s.unknowns();
  // b = b_static + F b_1: the unit load's harmonic-1 rows, and those of F = i.
  Eigen::VectorXd b_static = linear->load, b_re = Eigen::VectorXd::Zero(n), b_im = Eigen::VectorXd::Zero(n);
  b_re.segment(nc, 2 * nc) = linear->load.segment(nc, 2 * nc);
  b_static.segment(nc, 2 * nc).setZero();
  b_im.segment(nc, nc) = b_re.segment(2 * nc, nc);   // Re(i b1) = -Im b1 = the b rows
  b_im.segment(2 * nc, nc) = -b_re.segment(nc, nc);  // -Im(i b1) = -Re b1
  const Eigen::MatrixXd p = response_rows(s, omega, c.dof);
  const double scale = std::max(linear->operator_.cwiseAbs().maxCoeff(), 1e-300);  // [N/m]
  const auto system = [&](const Eigen::VectorXd& y) {
    const Eigen::VectorXd x = y.head(n);
    HarmonicBalance::ContactForces g = s.contact_forces(x);
    NewtonPoint pt;
    pt.valid = g.closed && g.force.allFinite();
    if (!pt.valid) return pt;
    pt.residual.resize(n + 2);
    pt.residual.head(n) = linear->operator_ * x + g.force - b_static - y[n] * b_re - y[n + 1] * b_im;
    pt.residual.tail(2) = scale * (p * y - Eigen::Vector2d(c.amplitude, 0.0));
    pt.jacobian.resize(n + 2, n + 2);
    pt.jacobian.topLeftCorner(n, n) = linear->operator_ + g.jacobian;
    pt.jacobian.col(n).head(n) = -b_re;
    pt.jacobian.col(n + 1).head(n) = -b_im;
    pt.jacobian.bottomRows(2) = scale * p;
    pt.valid = pt.residual.allFinite();
    pt.data = std::move(g.contacts);
    return pt;
  };
  const DampedNewtonOptions options{.tolerance = s.residual_tolerance(),
                                    .max_iterations = s.options().max_iterations,
                                    .max_backtracks = s.options().max_backtracks,
                                    .step_solve = NewtonStepSolve::minimum_norm,
                                    .levenberg_marquardt = true};
  // The caller's start, then the linear limits, each built only when the one before has failed
  // (along a stepped sine the previous point's solution converges in a few iterations).
  bool started = false;
  for (int k = initial ? 0 : 1; k < 3; ++k) {
    const std::optional<ControlledStart> start = k == 0 ? initial : linear_start(s, p, omega, c, k == 1);
    if (!start) continue;
    started = true;
    Eigen::VectorXd y(n + 2);
    y << start->x, start->force.real(), start->force.imag();
    DampedNewtonResult r = damped_newton(system, std::move(y), options);
    out.solution.iterations += r.iterations;
    const bool better = r.converged || !std::isfinite(out.solution.residual) || r.residual < out.solution.residual;
    if (better && std::isfinite(r.residual)) {
      out.solution.x = r.x.head(n);
      out.force = Complex(r.x[n], r.x[n + 1]);
      out.solution.residual = r.residual;
      out.solution.converged = r.converged;
      out.solution.failure =
          r.converged ? "" : fmt::format("{} (held response, omega = {:.6g} rad/s)", r.failure, omega);
      if (auto* contacts = std::any_cast<std::vector<friction::AftResult>>(&r.at.data))
        out.solution.contacts = std::move(*contacts);
    }
    if (r.converged) break;
  }
  if (!started) {
    out.solution.failure =
        fmt::format("no start: the linear limits do not move the held DOF at omega = {:.6g} rad/s", omega);
    return out;
  }
  if (out.solution.x.size() == 0) {
    out.solution.x = Eigen::VectorXd::Zero(n);
    out.solution.failure = fmt::format("no start could be evaluated at omega = {:.6g} rad/s", omega);
  }
  return out;
}

}  // namespace bb::hbm
