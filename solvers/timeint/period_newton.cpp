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

// The free sliders and other held directions, as rows replaced.
std::vector<PeriodEval::Held> held_rows(const PeriodEval& p, const PeriodLayout& layout, Index size) {
  std::vector<PeriodEval::Held> out = p.held;
  for (size_t c = 0; c < p.free_slider.size(); ++c)
    if (p.free_slider[c]) {
      const Index row = layout.slider_offset + static_cast<Index>(c);
      out.push_back({row, Eigen::RowVectorXd::Unit(size, row)});
    }
  return out;
}

// R = x(2 pi) - x(0), held directions kept.
VectorXd residual(const PeriodEval& p, const VectorXd& x, const PeriodLayout& layout) {
  VectorXd r = p.end - x;
  for (const PeriodEval::Held& h : held_rows(p, layout, x.size())) r[h.row] = 0.0;
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
    for (const PeriodEval::Held& h : held_rows(out.period, layout, x.size())) g.row(h.row) = h.gradient;
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
  // In coordinates whose held ones are the held directions (each repeats exactly: a multiplier 1
  // decoupled from the rest), then without them.
  const Index size = p.monodromy.rows();
  MatrixXd t = MatrixXd::Identity(size, size);
  std::vector<char> held(static_cast<size_t>(size), 0);
  for (const PeriodEval::Held& h : held_rows(p, layout, size))
    t.row(h.row) = h.gradient, held[static_cast<size_t>(h.row)] = 1;
  const MatrixXd changed = t * p.monodromy * t.inverse();
  std::vector<Index> kept;
  for (Index i = 0; i < size; ++i)
    if (!held[static_cast<size_t>(i)]) kept.push_back(i);
  const MatrixXd m = changed(kept, kept);
  Eigen::VectorXcd mu = Eigen::EigenSolver<MatrixXd>(m, false).eigenvalues();
  std::sort(mu.begin(), mu.end(), [](const auto& a, const auto& b) { return std::abs(a) > std::abs(b); });
  return mu;
}

}  // namespace bb::timeint
