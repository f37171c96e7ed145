#include "timeint/steady_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <deque>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace bb::timeint {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

void validate(double omega, const SteadyStateOptions& options) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("steady state: " + what); };
  if (!(std::isfinite(omega) && omega > 0.0)) fail(fmt::format("omega must be finite and > 0 (got {})", omega));
  if (options.dofs.empty()) fail("at least one DOF to track");
  if (options.harmonics < 0 || options.steps_per_period < 2 * (options.harmonics + 1))
    fail("harmonics >= 0 and steps_per_period >= 2 (harmonics + 1)");
  if (!(options.tolerance > 0.0) || options.min_cycles < 2 || options.max_cycles < options.min_cycles ||
      options.periods_analysed < 1 || options.periods_analysed > options.min_cycles)
    fail("tolerance > 0, 2 <= min_cycles <= max_cycles, 1 <= periods_analysed <= min_cycles");
  if (options.max_period_multiple < 1 || options.envelope_periods < 1)
    fail("max_period_multiple >= 1 and envelope_periods >= 1");
}

// The state at t = 0: from `start` (displacements, velocities, sliders) or the static initial
// state; nullopt (with out.failure set) when the static solve fails.
std::optional<DynamicState> initial_state(const NewmarkIntegrator& integrator, const Excitation& excitation,
                                          const SteadyStateOptions& options, const std::optional<DynamicState>& start,
                                          SteadyState& out) {
  if (start) {
    std::vector<double> sliders;
    for (const ContactSample& c : start->contacts) sliders.push_back(c.slider);
    return integrator.initial_state(start->displacement, start->velocity, 0.0, excitation, sliders);
  }
  const StaticState s = static_initial_state(integrator.model(), options.initial);
  if (!s.converged) {
    out.failure = "steady state: no static initial state: " + s.failure;
    return std::nullopt;
  }
  return integrator.initial_state(s.q, VectorXd::Zero(integrator.model().mass.rows()), 0.0, excitation, s.sliders);
}

// The largest sample-by-sample change between two periods relative to the DOF's largest value,
// over the tracked DOFs (columns), period means removed when drift is ignored.
double period_change(const MatrixXd& x, const MatrixXd& previous, bool ignore_drift) {
  double change = 0.0;
  for (Index j = 0; j < x.cols(); ++j) {
    VectorXd now = x.col(j), before = previous.col(j);
    if (ignore_drift) {
      now.array() -= now.mean();
      before.array() -= before.mean();
    }
    const double scale = x.col(j).cwiseAbs().maxCoeff();
    const double d = (now - before).cwiseAbs().maxCoeff();
    change = std::max(change, scale > 0.0 ? d / scale : (d > 0.0 ? INFINITY : 0.0));
  }
  return change;
}

// The first harmonic a1 - i b1 of each column of one period of n_t samples, from cos and sin at
// the samples (built once per run, used every period).
class FirstHarmonic {
 public:
  explicit FirstHarmonic(int n_t) : cosine_(n_t), sine_(n_t) {
    for (int k = 0; k < n_t; ++k) {
      cosine_[k] = std::cos(2.0 * std::numbers::pi * k / n_t);
      sine_[k] = std::sin(2.0 * std::numbers::pi * k / n_t);
    }
  }
  Eigen::RowVectorXcd operator()(const MatrixXd& x) const {
    const double scale = 2.0 / static_cast<double>(x.rows());
    Eigen::RowVectorXcd z(x.cols());
    for (Index j = 0; j < x.cols(); ++j)
      z[j] = scale * std::complex<double>(x.col(j).dot(cosine_), -x.col(j).dot(sine_));
    return z;
  }

 private:
  VectorXd cosine_, sine_;
};

// The smallest k in [2, max_period_multiple] for which the last of `periods` repeats the one k
// periods before it to the tolerance; 0 when none does.
int repeating_multiple(const std::deque<MatrixXd>& periods, const SteadyStateOptions& options) {
  const size_t last = periods.size() - 1;
  for (size_t k = 2; k <= std::min(last, static_cast<size_t>(options.max_period_multiple)); ++k)
    if (period_change(periods[last], periods[last - k], options.ignore_drift) <= options.tolerance)
      return static_cast<int>(k);
  return 0;
}

// DFT over the last whole periods, their linear trend removed when drift is ignored.
void analyse(std::deque<MatrixXd>& periods, const SteadyStateOptions& options, SteadyState& out) {
  const int n_t = options.steps_per_period;
  const Index nd = static_cast<Index>(options.dofs.size());
  if (options.ignore_drift && out.drift.size() == nd) {
    // Remove the linear trend (drift per period spread over the samples) from the analysed periods.
    for (size_t p = 0; p < periods.size(); ++p)
      for (int k = 0; k < n_t; ++k)
        periods[p].row(k) -= out.drift.transpose() *
                             ((static_cast<double>(p) * n_t + k) / n_t - 0.5 * static_cast<double>(periods.size()));
  }
  fill_harmonics(periods, options.harmonics, out);
}

}  // namespace

void fill_harmonics(const std::deque<MatrixXd>& periods, int harmonics, SteadyState& out) {
  const Index nd = periods.front().cols();
  const auto n_t = static_cast<int>(periods.front().rows());
  const double samples = static_cast<double>(n_t) * static_cast<double>(periods.size());
  out.coefficients = MatrixXd::Zero(nd, 2 * harmonics + 1);
  for (const MatrixXd& x : periods) {
    for (int k = 0; k < n_t; ++k) {
      const double theta = 2.0 * std::numbers::pi * k / n_t;
      for (Index j = 0; j < nd; ++j) {
        out.coefficients(j, 0) += x(k, j) / samples;
        for (int h = 1; h <= harmonics; ++h) {
          out.coefficients(j, 2 * h - 1) += 2.0 * x(k, j) * std::cos(h * theta) / samples;
          out.coefficients(j, 2 * h) += 2.0 * x(k, j) * std::sin(h * theta) / samples;
        }
      }
    }
  }
  fill_amplitude_and_phase(out);
}

void fill_amplitude_and_phase(SteadyState& out) {
  const Index nd = out.coefficients.rows();
  const auto harmonics = static_cast<int>((out.coefficients.cols() - 1) / 2);
  out.amplitude = MatrixXd::Zero(nd, harmonics + 1);
  out.phase = MatrixXd::Zero(nd, harmonics + 1);
  for (Index j = 0; j < nd; ++j) {
    out.amplitude(j, 0) = std::abs(out.coefficients(j, 0));
    for (int h = 1; h <= harmonics; ++h) {
      const double a = out.coefficients(j, 2 * h - 1), b = out.coefficients(j, 2 * h);
      out.amplitude(j, h) = std::hypot(a, b);
      out.phase(j, h) = std::atan2(-b, a);
    }
  }
}

SteadyState steady_state(const friction::FrictionModel& model, double omega, const SteadyStateOptions& options,
                         const std::optional<DynamicState>& start) {
  validate(omega, options);
  const int n_t = options.steps_per_period;
  NewmarkOptions nm = options.newmark;
  nm.time_step = 2.0 * std::numbers::pi / (omega * n_t);
  const NewmarkIntegrator integrator(model, nm);
  const Index n = integrator.model().mass.rows();
  for (const Index i : options.dofs)
    if (i < 0 || i >= n)
      throw std::invalid_argument(fmt::format("steady state: tracked DOF {} is not in [0, {})", i, n));
  const Excitation excitation = model_excitation(integrator.model(), omega);

  SteadyState out;
  out.omega = omega;
  out.drift = VectorXd::Zero(static_cast<Index>(options.dofs.size()));
  std::optional<DynamicState> initial = initial_state(integrator, excitation, options, start, out);
  if (!initial) return out;
  DynamicState state = std::move(*initial);

  const Index nd = static_cast<Index>(options.dofs.size());
  // The last periods, n_t x nd samples each: enough for the DFT (periods_analysed) and for the test
  // of a repetition after k = 2..max_period_multiple periods.
  const auto kept = static_cast<size_t>(std::max(options.periods_analysed, options.max_period_multiple + 1));
  std::deque<MatrixXd> periods;
  const FirstHarmonic first_harmonic(n_t);
  std::deque<Eigen::RowVectorXcd> harmonics;  // each period's first harmonics, the last envelope_periods
  std::vector<std::vector<ContactSample>> loop;
  while (out.cycles < options.max_cycles) {
    MatrixXd x(n_t, nd);
    loop.assign(state.contacts.size(), {});
    const WorkLedger work0 = state.work;
    const double energy0 = integrator.mechanical_energy(state);
    for (int k = 0; k < n_t; ++k) {
      for (Index j = 0; j < nd; ++j) x(k, j) = state.displacement[options.dofs[static_cast<size_t>(j)]];
      for (size_t c = 0; c < state.contacts.size(); ++c) loop[c].push_back(state.contacts[c]);
      const StepReport r = integrator.step(state, excitation);
      if (!r.converged) {
        out.failure =
            fmt::format("steady state at omega = {:.9g} rad/s, period {}: {}", omega, out.cycles + 1, r.failure);
        out.final_state = state;
        return out;
      }
      out.total_iterations += r.iterations;
      out.max_iterations = std::max(out.max_iterations, r.iterations);
    }
    for (size_t c = 0; c < state.contacts.size(); ++c) loop[c].push_back(state.contacts[c]);
    ++out.cycles;
    out.cycle_work = {.excitation = state.work.excitation - work0.excitation,
                      .viscous = state.work.viscous - work0.viscous,
                      .friction = state.work.friction - work0.friction,
                      .normal = state.work.normal - work0.normal};
    out.energy_change = integrator.mechanical_energy(state) - energy0;
    if (!periods.empty()) {
      out.drift = x.colwise().mean().transpose() - periods.back().colwise().mean().transpose();
      out.change = period_change(x, periods.back(), options.ignore_drift);
    }
    harmonics.push_back(first_harmonic(x));
    if (static_cast<int>(harmonics.size()) > options.envelope_periods) harmonics.pop_front();
    periods.push_back(std::move(x));
    if (periods.size() > kept) periods.pop_front();
    if (out.cycles >= options.min_cycles && out.change <= options.tolerance) {
      out.converged = true;
      break;
    }
  }
  // A motion that repeats is its last period; the earlier ones were its transient.
  if (out.converged) harmonics.erase(harmonics.begin(), harmonics.end() - 1);
  out.period_harmonics = Eigen::MatrixXcd(static_cast<Index>(harmonics.size()), nd);
  for (size_t p = 0; p < harmonics.size(); ++p) out.period_harmonics.row(static_cast<Index>(p)) = harmonics[p];
  out.envelope = MatrixXd::Constant(nd, 2, NAN);
  if (!harmonics.empty()) {
    out.envelope.col(0) = out.period_harmonics.cwiseAbs().colwise().minCoeff().transpose();
    out.envelope.col(1) = out.period_harmonics.cwiseAbs().colwise().maxCoeff().transpose();
  }
  out.period_multiple = out.converged ? 1 : repeating_multiple(periods, options);
  // The DFT over the last periods_analysed periods, or over one whole repetition of a subharmonic motion.
  const size_t analysed = std::min(
      periods.size(), static_cast<size_t>(out.period_multiple > 1 ? out.period_multiple : options.periods_analysed));
  periods.erase(periods.begin(), periods.end() - static_cast<std::ptrdiff_t>(analysed));
  if (out.period_multiple > 1) {
    out.failure = fmt::format(
        "steady state at omega = {:.9g} rad/s not reached in {} periods: the motion repeats every {} periods (a "
        "subharmonic response; cycle-to-cycle change {:.3e} > tolerance {:.3e})",
        omega, out.cycles, out.period_multiple, out.change, options.tolerance);
  } else if (!out.converged) {
    out.failure = fmt::format(
        "steady state at omega = {:.9g} rad/s not reached in {} periods: cycle-to-cycle "
        "change {:.3e} > tolerance {:.3e} (largest drift of a period mean {:.3e} m per period); no repetition "
        "within {} periods; first-harmonic amplitude over the last {} periods {:.4g} to {:.4g} m",
        omega, out.cycles, out.change, options.tolerance, out.drift.cwiseAbs().maxCoeff(), options.max_period_multiple,
        harmonics.size(), out.envelope(0, 0), out.envelope(0, 1));
  }
  analyse(periods, options, out);
  out.contacts = std::move(loop);
  out.final_state = state;
  return out;
}

}  // namespace bb::timeint
