#include "timeint/shooting.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/constants.hpp"
#include "timeint/period_newton.hpp"

namespace bb::timeint {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using friction::ContactState;

namespace {

VectorXd stack(const FlowState& s) {
  VectorXd x(s.q.size() + s.p.size() + s.w.size());
  x << s.q, s.p, s.w;
  return x;
}

FlowState unstack(const PiecewiseFlow& flow, const VectorXd& x) {
  const Index n = flow.dofs();
  FlowState s;
  s.q = x.head(n);
  s.p = x.segment(n, n);
  s.w = x.tail(flow.contacts());
  flow.settle(s);
  return s;
}

// One period from x: the end state, the monodromy (when asked) and which sliders never moved.
PeriodEval one_period(const PiecewiseFlow& flow, const VectorXd& x, int steps, int max_events, bool jacobian) {
  PeriodEval out;
  FlowState end = unstack(flow, x);
  const std::vector<ContactState> modes0 = end.modes;
  if (jacobian) out.monodromy = flow.start_jacobian(end);
  PiecewiseFlow::Advance log;
  for (int k = 1; k <= steps && log.failure.empty(); ++k)
    flow.advance(end, kTwoPi * k / steps, jacobian ? &out.monodromy : nullptr, max_events, log);
  out.end = stack(end);
  out.transitions = log.events;
  out.failure = log.failure;
  out.free_slider.resize(modes0.size());
  const bool rigid_stick = flow.rigid_stick();
  std::vector<char> used(static_cast<size_t>(flow.dofs()), 0);
  for (size_t c = 0; c < modes0.size(); ++c) {
    const bool free = modes0[c] == ContactState::stick && (log.switched.empty() || !log.switched[c]);
    out.free_slider[c] = free && !rigid_stick;
    if (!free || !rigid_stick) continue;
    // Held rigidly all period, the contact stays at any u: u is held, in place of the equation of
    // the DOF it moves most (the DOFs' equations combine to u's, which repeats by itself).
    const Eigen::RowVectorXd& at = flow.tangential(static_cast<Index>(c));
    Index dof = -1;
    for (Index d = 0; d < at.size(); ++d)
      if (!used[static_cast<size_t>(d)] && at[d] != 0.0 && (dof < 0 || std::abs(at[d]) > std::abs(at[dof]))) dof = d;
    if (dof < 0) continue;
    used[static_cast<size_t>(dof)] = 1;
    Eigen::RowVectorXd gradient = Eigen::RowVectorXd::Zero(x.size());
    gradient.head(flow.dofs()) = at;
    out.held.push_back({dof, gradient});
  }
  return out;
}

// The recorded period: samples at the sub-interval ends, located extremes, harmonics.
void record(const PiecewiseFlow& flow, const VectorXd& x, const ShootingOptions& o, ShootingResult& out) {
  const int n_t = o.steps_per_period;
  const auto nd = static_cast<Index>(o.dofs.size());
  FlowState s = unstack(flow, x);
  out.start = s;
  out.largest = VectorXd::Zero(nd);
  MatrixXd& samples = out.samples;
  samples.resize(n_t + 1, nd);
  out.steady.contacts.assign(static_cast<size_t>(flow.contacts()), {});
  PiecewiseFlow::Advance log;
  MatrixXd integrals = MatrixXd::Zero(nd, 2 * o.harmonics + 1);  // of q, q cos h theta, q sin h theta
  for (int k = 0; k <= n_t; ++k) {
    if (k > 0) flow.advance(s, kTwoPi * k / n_t, nullptr, o.max_events, log, o.dofs, &out.largest, &integrals);
    for (Index j = 0; j < nd; ++j) samples(k, j) = s.q[o.dofs[static_cast<size_t>(j)]];
    for (Index c = 0; c < flow.contacts(); ++c)
      out.steady.contacts[static_cast<size_t>(c)].push_back(flow.sample(s, c));
  }
  // The Fourier integrals of the exact motion: no aliasing of the samples.
  out.steady.coefficients = integrals / kPi;
  out.steady.coefficients.col(0) /= 2.0;
  fill_amplitude_and_phase(out.steady);
}

}  // namespace

void validate_rigid_stick(const friction::FrictionModel& model) {
  if (model.contacts.empty()) return;
  MatrixXd rows(static_cast<Index>(model.contacts.size()), model.mass.rows());
  for (size_t c = 0; c < model.contacts.size(); ++c) rows.row(static_cast<Index>(c)) = model.contacts[c].tangential;
  Eigen::FullPivLU<MatrixXd> lu(rows);
  lu.setThreshold(1e-10);
  if (lu.rank() < rows.rows())
    throw std::invalid_argument(
        fmt::format("Coulomb's stick holds each stuck contact's u, so the {} contacts' tangential directions must be "
                    "independent (their rank is {})",
                    rows.rows(), lu.rank()));
}

void validate_shooting(const friction::FrictionModel& model, double omega, const ShootingOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("shooting: " + what); };
  if (!(std::isfinite(omega) && omega > 0.0)) fail(fmt::format("omega must be finite and > 0 (got {})", omega));
  if (o.dofs.empty()) fail("at least one DOF to report");
  for (const Index d : o.dofs)
    if (d < 0 || d >= model.mass.rows()) fail(fmt::format("DOF {} is not in [0, {})", d, model.mass.rows()));
  if (o.harmonics < 0 || o.steps_per_period < 2 * (o.harmonics + 1))
    fail("harmonics >= 0 and steps_per_period >= 2 (harmonics + 1)");
  if (!(o.tolerance > 0.0) || o.max_iterations < 1 || o.warmup_periods < 0 || o.max_events < 1)
    fail("tolerance > 0, max_iterations >= 1, warmup_periods >= 0 and max_events >= 1");
  if (o.rigid_stick) validate_rigid_stick(model);
}

VectorXd warm_start(const friction::FrictionModel& model, const PeriodMap& map, Index size, Index slider_offset,
                    const ShootingOptions& o, int& periods, std::string& failure) {
  const Index n = model.mass.rows();
  const StaticState st = static_initial_state(model, o.initial);
  VectorXd x = VectorXd::Zero(size);
  if (st.converged) {
    x.head(n) = st.q;
    for (size_t c = 0; c < st.sliders.size(); ++c) x[slider_offset + static_cast<Index>(c)] = st.sliders[c];
  }
  for (int k = 0; k < o.warmup_periods; ++k) {
    const PeriodEval p = map(x, false);
    ++periods;
    if (!p.failure.empty()) {
      failure = p.failure;
      return x;
    }
    const double change = (p.end - x).head(2 * n).cwiseAbs().maxCoeff();
    x = p.end;
    if (change <= 1e-3 * x.head(2 * n).cwiseAbs().maxCoeff()) break;
  }
  return x;
}

bool take_newton(const PeriodNewtonResult& newton, const PeriodLayout& layout, bool floquet, ShootingResult& out) {
  out.steady.cycles += newton.periods;
  out.steady.total_iterations = newton.iterations;
  out.residual = newton.residual;
  if (!newton.converged) {
    out.steady.failure = newton.failure;
    return false;
  }
  out.steady.converged = true;
  out.transitions = newton.period.transitions;
  if (floquet) {
    out.multipliers = floquet_multipliers(newton.period, layout);
    out.largest_multiplier = out.multipliers.size() > 0 ? std::abs(out.multipliers[0]) : 0.0;
    out.stable = out.largest_multiplier < 1.0;
  }
  return true;
}

ShootingResult shooting(const friction::FrictionModel& input, double omega, const ShootingOptions& o,
                        const std::optional<FlowState>& start) {
  friction::FrictionModel model = input;
  friction::validate_model(model, "shooting");
  validate_shooting(model, omega, o);
  const PiecewiseFlow flow(model, omega, kTwoPi / o.steps_per_period, o.rigid_stick);
  ShootingResult out;
  out.steady.omega = omega;
  out.largest_multiplier = std::numeric_limits<double>::quiet_NaN();
  int& periods = out.steady.cycles;
  const PeriodLayout layout{.motion = 2 * flow.dofs(), .slider_offset = 2 * flow.dofs()};
  const PeriodMap map = [&](const VectorXd& from, bool jacobian) {
    return one_period(flow, from, o.steps_per_period, o.max_events, jacobian);
  };
  VectorXd x = start ? stack(*start)
                     : warm_start(model, map, flow.state_size(), layout.slider_offset, o, periods, out.steady.failure);
  if (!out.steady.failure.empty()) return out;
  const PeriodNewtonResult newton = newton_on_period(map, x, layout, o.tolerance, o.max_iterations, omega);
  if (!take_newton(newton, layout, o.floquet, out)) return out;
  record(flow, newton.x, o, out);
  ++periods;
  return out;
}

}  // namespace bb::timeint
