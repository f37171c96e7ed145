#include "timeint/period_newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace bb::timeint {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

double scale_of(const VectorXd& x, Index motion) { return x.head(motion).cwiseAbs().maxCoeff(); }

// R = x(2 pi) - x(0), free sliders held.
VectorXd residual(const PeriodEval& p, const VectorXd& x, const PeriodLayout& layout) {
  VectorXd r = p.end - x;
  for (size_t c = 0; c < p.free_slider.size(); ++c)
    if (p.free_slider[c]) r[layout.slider_offset + static_cast<Index>(c)] = 0.0;
  return r;
}

}  // namespace

PeriodNewtonResult newton_on_period(const PeriodMap& map, VectorXd x, const PeriodLayout& layout, double tolerance,
                                    int max_iterations, double omega) {
  PeriodNewtonResult out;
  const auto fail = [&](const std::string& why) {
    out.failure = fmt::format("shooting at omega = {:.9g} rad/s: {} after {} Newton iterations, |R| = {:.3e} m", omega,
                              why, out.iterations, out.residual);
    out.x = x;
    return out;
  };
  out.period = map(x, true);
  ++out.periods;
  VectorXd r = residual(out.period, x, layout);
  out.residual = r.cwiseAbs().maxCoeff();
  while (true) {
    if (!out.period.failure.empty()) return fail(out.period.failure);
    if (out.residual <= tolerance * scale_of(x, layout.motion)) break;
    if (out.iterations >= max_iterations) return fail("no convergence");
    ++out.iterations;
    MatrixXd g = out.period.monodromy - MatrixXd::Identity(x.size(), x.size());
    for (size_t c = 0; c < out.period.free_slider.size(); ++c)
      if (out.period.free_slider[c]) {
        const Index row = layout.slider_offset + static_cast<Index>(c);
        g.row(row).setZero();
        g(row, row) = 1.0;
      }
    const VectorXd dx = g.colPivHouseholderQr().solve(-r);
    if (!dx.allFinite()) return fail("singular monodromy - I");
    // At the rounding floor |R| stops falling; a correction below the tolerance ends the iteration.
    if (dx.head(layout.motion).cwiseAbs().maxCoeff() <= tolerance * scale_of(x, layout.motion)) {
      x += dx;
      break;
    }
    bool accepted = false;
    // The full step carries its monodromy (it is usually taken); a shortened one is tried without
    // and, once accepted, integrated again with it.
    for (double lambda = 1.0; lambda > 1e-4 && !accepted; lambda *= 0.5) {
      const VectorXd trial = x + lambda * dx;
      PeriodEval q = map(trial, lambda == 1.0);
      ++out.periods;
      const VectorXd rq = residual(q, trial, layout);
      const double norm = rq.cwiseAbs().maxCoeff();
      if (q.failure.empty() && norm < (1.0 - 1e-4 * lambda) * out.residual) {
        if (lambda != 1.0) {
          q = map(trial, true);
          ++out.periods;
        }
        x = trial, out.period = std::move(q), r = rq, out.residual = norm, accepted = true;
      }
    }
    if (!accepted) return fail("line search failed");
  }
  out.converged = true;
  out.x = std::move(x);
  return out;
}

Eigen::VectorXcd floquet_multipliers(const PeriodEval& p, const PeriodLayout& layout) {
  std::vector<Index> kept;
  for (Index i = 0; i < p.monodromy.rows(); ++i) {
    const Index c = i - layout.slider_offset;
    const bool free = c >= 0 && c < static_cast<Index>(p.free_slider.size()) && p.free_slider[static_cast<size_t>(c)];
    if (!free) kept.push_back(i);
  }
  const MatrixXd m = p.monodromy(kept, kept);
  Eigen::VectorXcd mu = Eigen::EigenSolver<MatrixXd>(m, false).eigenvalues();
  std::sort(mu.begin(), mu.end(), [](const auto& a, const auto& b) { return std::abs(a) > std::abs(b); });
  return mu;
}

}  // namespace bb::timeint
