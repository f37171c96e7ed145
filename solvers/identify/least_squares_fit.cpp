#include "identify/least_squares_fit.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <numeric>
#include <random>

#include "common/parallel_indices.hpp"
#include "distributed/byte_record.hpp"
#include "distributed/distributed.hpp"
#include "identify/central_differences.hpp"
#include "identify/fit_identifiability.hpp"

namespace bb {
namespace {

// The robust loss per point: each residual r is replaced by sign(r) sqrt(rho(r^2)), so that the sum
// of squares Ceres minimizes is sum rho(r_k^2) point by point (Huber: rho(s) = s up to b^2, then
// 2 b sqrt(s) - b^2; Cauchy: b^2 log(1 + s / b^2)). Given to Ceres as one LossFunction it would act
// on the whole block's sum, which changes no minimizer: an outlier would weigh as much as any
// point. A stated prior (quantity "prior") is Gaussian and keeps its residual.
struct RobustLoss {
  enum class Kind { none, huber, cauchy } kind = Kind::none;
  double scale = 1.0;  // b, in sigmas

  static RobustLoss of(const CalibrationSpec& cal) {
    return {cal.loss == "huber" ? Kind::huber : cal.loss == "cauchy" ? Kind::cauchy : Kind::none, cal.loss_scale};
  }
  // (r~, dr~/dr) of a residual r.
  std::pair<double, double> operator()(double r, const FitPoint& p) const {
    const double a = std::abs(r), b = scale;
    if (kind == Kind::none || p.quantity == "prior" || a == 0.0) return {r, 1.0};
    if (kind == Kind::huber) {
      if (a <= b) return {r, 1.0};
      const double t = std::sqrt(2.0 * b * a - b * b);
      return {std::copysign(t, r), b / t};
    }
    const double l = std::log1p(a * a / (b * b));
    const double t = b * std::sqrt(l);
    return {std::copysign(t, r), b * a / (std::sqrt(l) * (b * b + a * a))};
  }
};

// The parameters' values at fit values x (CalibrationParameter::from_fit).
std::vector<double> values_at(const CalibrationSpec& cal, const double* x) {
  std::vector<double> values(cal.parameters.size());
  for (size_t i = 0; i < values.size(); ++i) values[i] = cal.parameters[i].from_fit(x[i]);
  return values;
}

// The residuals r_k = (computed_k - measured_k) / sigma_k (the misfit in units of the stated
// uncertainty, through the robust loss) at fit values, for central differences; several may run at
// once (the Jacobian's columns on workers), hence the atomic count.
struct NumericResidual {
  const FitEvaluator* evaluate;
  const CalibrationSpec* cal;
  int* evaluations;
  RobustLoss loss;
  bool operator()(const std::vector<double>& x, double* residuals) const {
    const std::vector<double> values = values_at(*cal, x.data());
    try {
      const auto points = (*evaluate)(values, false);
      std::atomic_ref<int>(*evaluations).fetch_add(1);
      for (const FitPoint& p : points)
        if (!std::isfinite(p.computed)) return false;  // a peak or mode not found there: Ceres shrinks the step
      for (size_t k = 0; k < points.size(); ++k) residuals[k] = loss(points[k].residual(), points[k]).first;
      return true;
    } catch (const std::exception&) {
      return false;  // an impossible geometry or a failed solve: Ceres shrinks the step
    }
  }
};

// The same residuals with the Jacobian from the model's own sensitivities: one model run per
// evaluation instead of 2 n + 1 (J_kj = dr_k/dx_j = (dr_k/d log p_j) (dp_j/dx_j) / p_j). Where a
// point has no derivative (a peak on a corner of its curve, a singular Jacobian), that evaluation's
// Jacobian is taken by central differences instead, and counted.
class AnalyticResidual : public ceres::CostFunction {
 public:
  AnalyticResidual(const FitEvaluator* evaluate, const CalibrationSpec* cal, int* evaluations, int residuals,
                   size_t workers, int* fallbacks, int* one_sided, RobustLoss loss, std::vector<size_t> numeric)
      : evaluate_(evaluate),
        cal_(cal),
        numeric_(std::move(numeric)),
        evaluations_(evaluations),
        fallbacks_(fallbacks),
        loss_(loss),
        differences_(NumericResidual{evaluate, cal, evaluations, loss}, static_cast<int>(cal->parameters.size()),
                     residuals, cal->derivative_step, workers, one_sided) {
    set_num_residuals(residuals);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(cal->parameters.size()));
  }

  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    const size_t n = static_cast<size_t>(parameter_block_sizes()[0]);
    const std::vector<double> values = values_at(*cal_, x[0]);
    const bool jacobian = jacobians && jacobians[0];
    try {
      const auto points = (*evaluate_)(values, jacobian);
      ++*evaluations_;
      if (points.size() != static_cast<size_t>(num_residuals())) return false;
      bool differentiable = true;
      for (size_t k = 0; k < points.size(); ++k) {
        const FitPoint& p = points[k];
        if (!std::isfinite(p.computed)) return false;  // as NumericResidual: Ceres shrinks the step
        const auto [r, slope] = loss_(p.residual(), p);
        residuals[k] = r;
        if (!jacobian) continue;
        differentiable = differentiable && p.gradient.size() == n;
        for (size_t j = 0; j < n && differentiable; ++j) {
          if (std::find(numeric_.begin(), numeric_.end(), j) != numeric_.end()) continue;
          const double g = slope * p.gradient[j] * cal_->parameters[j].value_per_fit(values[j]) / values[j];
          differentiable = std::isfinite(g);
          jacobians[0][k * n + j] = g;
        }
      }
      if (differentiable)
        return !jacobian || numeric_.empty() ||
               differences_.Columns(std::vector<double>(x[0], x[0] + n), residuals, numeric_, jacobians[0]);
      ++*fallbacks_;
      return differences_.Evaluate(x, residuals, jacobians);
    } catch (const std::exception&) {
      return false;
    }
  }

 private:
  const FitEvaluator* evaluate_;
  const CalibrationSpec* cal_;
  std::vector<size_t> numeric_;  // columns the model does not differentiate
  int* evaluations_;
  int* fallbacks_;
  RobustLoss loss_;
  CentralDifferences differences_;
};

class IterationTrace : public ceres::IterationCallback {
 public:
  IterationTrace(const FitProgress& progress, std::vector<std::pair<int, double>>& history, int start, int starts,
                 int max_iterations)
      : progress_(progress), history_(history), start_(start), starts_(starts), max_iterations_(max_iterations) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    history_.emplace_back(s.iteration, s.cost);
    if (progress_)
      progress_({start_, starts_, s.iteration, max_iterations_, s.cost, s.gradient_max_norm, s.step_is_successful});
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const FitProgress& progress_;
  std::vector<std::pair<int, double>>& history_;
  int start_, starts_, max_iterations_;
};

// One start's run, as a rank sends it to the others.
struct StartRun {
  CalibrationStart result;
  std::vector<double> x;
  std::string message, brief;
  bool failed = false;  // stopped because the model could not be run where Ceres asked
  std::vector<std::pair<int, double>> history;
  int evaluations = 0, fallbacks = 0, one_sided = 0;
};

std::string to_bytes(const StartRun& r) {
  distributed::ByteWriter w;
  const CalibrationStart& c = r.result;
  w.put(c.start).put(c.values).put(c.initial_cost).put(c.final_cost).put(c.iterations);
  w.put(static_cast<int>(c.converged)).put(static_cast<int>(c.evaluated));
  w.put(r.x).put(r.message).put(r.brief).put(static_cast<int>(r.failed));
  std::vector<int> iterations;
  std::vector<double> costs;
  for (const auto& [i, cost] : r.history) {
    iterations.push_back(i);
    costs.push_back(cost);
  }
  w.put(iterations).put(costs).put(r.evaluations).put(r.fallbacks).put(r.one_sided);
  return w.bytes();
}

StartRun from_bytes(const std::string& bytes) {
  distributed::ByteReader in(bytes);
  StartRun r;
  CalibrationStart& c = r.result;
  int converged = 0, evaluated = 0, failed = 0;
  in.get(c.start);
  in.get(c.values);
  in.get(c.initial_cost);
  in.get(c.final_cost);
  in.get(c.iterations);
  in.get(converged);
  in.get(evaluated);
  in.get(r.x);
  in.get(r.message);
  in.get(r.brief);
  in.get(failed);
  std::vector<int> iterations;
  std::vector<double> costs;
  in.get(iterations);
  in.get(costs);
  in.get(r.evaluations);
  in.get(r.fallbacks);
  in.get(r.one_sided);
  c.converged = converged != 0;
  c.evaluated = evaluated != 0;
  r.failed = failed != 0;
  for (size_t k = 0; k < iterations.size() && k < costs.size(); ++k) r.history.emplace_back(iterations[k], costs[k]);
  return r;
}

// Under mpirun (ranks sharing out independent runs) rank r runs starts r, r + ranks, ... and every
// rank receives all of them; otherwise every start here, on `workers` threads.
void run_starts_over_ranks(std::vector<StartRun>& runs, size_t workers, const std::function<void(size_t)>& run_start) {
  const int ranks = distributed::size();
  if (ranks == 1 || distributed::shared_solves()) {
    for_each_index(runs.size(), workers, run_start);
    return;
  }
  const std::vector<size_t> mine = distributed::share_of_rank(runs.size(), distributed::rank());
  for_each_index(mine.size(), std::min(workers, std::max<size_t>(mine.size(), 1)),
                 [&](size_t k) { run_start(mine[k]); });
  distributed::ByteWriter w;
  for (size_t s : mine) w.put(to_bytes(runs[s]));
  const std::vector<std::string> all = distributed::gather_from_all(w.bytes());
  for (int r = 0; r < ranks; ++r) {
    distributed::ByteReader in(all[static_cast<size_t>(r)]);
    for (size_t s : distributed::share_of_rank(runs.size(), r)) {
      std::string bytes;
      in.get(bytes);
      runs[s] = from_bytes(bytes);
    }
  }
}

// The spec's values, then starts - 1 points of a Latin hypercube in the fit values within the bounds.
std::vector<std::vector<double>> start_points(const CalibrationSpec& cal) {
  const size_t n = cal.parameters.size();
  std::vector<double> first(n);
  for (size_t i = 0; i < n; ++i) first[i] = cal.parameters[i].start;
  std::vector<std::vector<double>> starts{first};
  if (cal.starts <= 1) return starts;
  std::mt19937 rng(cal.seed);
  const int m = cal.starts - 1;
  std::vector<std::vector<int>> strata(n);
  for (size_t i = 0; i < n; ++i) {
    strata[i].resize(static_cast<size_t>(m));
    std::iota(strata[i].begin(), strata[i].end(), 0);
    std::shuffle(strata[i].begin(), strata[i].end(), rng);
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < m; ++k) {
    std::vector<double> p(n);
    for (size_t i = 0; i < n; ++i) {
      const CalibrationParameter& q = cal.parameters[i];
      const double lo = q.to_fit(q.lower), hi = q.to_fit(q.upper);
      p[i] = q.from_fit(lo + (hi - lo) * (strata[i][static_cast<size_t>(k)] + unit(rng)) / m);
    }
    starts.push_back(p);
  }
  return starts;
}

}  // namespace

CalibrationOutcome fit_parameters(const CalibrationSpec& cal, const FitEvaluator& evaluate, bool analytic,
                                  int residuals, const FitProgress& progress,
                                  const std::vector<bool>& numeric_columns) {
  CalibrationOutcome out;
  out.spec = cal;
  const size_t n = cal.parameters.size();
  const std::vector<std::vector<double>> starts = start_points(cal);
  // The cores left to each start run its Jacobian's columns (a single start: all of them).
  const size_t at_once = worker_count(starts.size(), cal.threads);
  const size_t budget = worker_count(std::numeric_limits<size_t>::max(), cal.threads);
  const size_t column_workers = std::max<size_t>(1, budget / std::max<size_t>(1, at_once));
  // The problem for fit values x (Ceres keeps a pointer to x: one problem per start).
  const auto build = [&](std::vector<double>& x, ceres::Problem& problem, int* evaluations, int* fallbacks,
                         int* one_sided) {
    ceres::CostFunction* cost = nullptr;
    const RobustLoss loss = RobustLoss::of(cal);
    if (analytic) {
      std::vector<size_t> numeric;
      for (size_t j = 0; j < numeric_columns.size(); ++j)
        if (numeric_columns[j]) numeric.push_back(j);
      cost = new AnalyticResidual(&evaluate, &cal, evaluations, residuals, column_workers, fallbacks, one_sided, loss,
                                  std::move(numeric));
    } else {
      // derivative_step (default 1e-4): above the eigensolver's 1e-10 noise, below the model's curvature.
      cost = new CentralDifferences(NumericResidual{&evaluate, &cal, evaluations, loss}, static_cast<int>(n), residuals,
                                    cal.derivative_step, column_workers, one_sided);
    }
    problem.AddResidualBlock(cost, nullptr, x.data());
    for (size_t i = 0; i < n; ++i) {
      const CalibrationParameter& q = cal.parameters[i];
      problem.SetParameterLowerBound(x.data(), static_cast<int>(i), q.to_fit(q.lower));
      problem.SetParameterUpperBound(x.data(), static_cast<int>(i), q.to_fit(q.upper));
    }
  };
  ceres::Solver::Options options;
  options.max_num_iterations = cal.max_iterations;
  options.linear_solver_type = ceres::DENSE_QR;
  options.function_tolerance = cal.function_tolerance;
  options.parameter_tolerance = 1e-8;
  options.update_state_every_iteration = true;
  // No projected line search after each step: with bounds, Ceres would take the gradient at every
  // candidate (a whole Jacobian, 2 n model runs) before evaluating its cost, doubling the runs per
  // iteration; Ceres still projects each step onto the bounds.
  options.max_num_line_search_step_size_iterations = 0;
  // Every start is its own problem: they run on `threads` workers (and, under mpirun, shared out
  // over the ranks), and the best is chosen in start order afterwards, so the outcome is the serial
  // one whatever the workers' timing.
  std::vector<StartRun> runs(starts.size());
  std::mutex progress_lock;
  FitProgress locked_progress;  // the caller's, one line at a time
  if (progress)
    locked_progress = [&](const FitIteration& it) {
      const std::lock_guard<std::mutex> guard(progress_lock);
      progress(it);
    };
  const auto run_start = [&](size_t s) {
    StartRun& run = runs[s];
    run.x.resize(n);
    for (size_t i = 0; i < n; ++i) run.x[i] = cal.parameters[i].to_fit(starts[s][i]);
    ceres::Problem problem;
    build(run.x, problem, &run.evaluations, &run.fallbacks, &run.one_sided);
    IterationTrace trace(locked_progress, run.history, static_cast<int>(s + 1), static_cast<int>(starts.size()),
                         cal.max_iterations);
    ceres::Solver::Options o = options;
    o.callbacks.push_back(&trace);
    ceres::Solver::Summary summary;
    ceres::Solve(o, &problem, &summary);
    CalibrationStart& r = run.result;
    r.start = starts[s];
    r.values = values_at(cal, run.x.data());
    // Ceres gives -1 for the costs of a start whose values the model could not be run at.
    r.evaluated = summary.initial_cost >= 0.0;
    r.initial_cost = r.evaluated ? summary.initial_cost : NAN;
    r.final_cost = r.evaluated ? summary.final_cost : NAN;
    r.iterations = static_cast<int>(summary.iterations.size());
    r.converged = r.evaluated && summary.termination_type == ceres::CONVERGENCE;
    run.message = summary.message;
    run.brief = summary.BriefReport();
    run.failed = summary.termination_type == ceres::FAILURE;
  };
  run_starts_over_ranks(runs, worker_count(starts.size(), cal.threads), run_start);
  if (const auto ranks = static_cast<size_t>(distributed::size());
      ranks > starts.size() && !distributed::shared_solves())
    out.warnings.push_back(
        fmt::format("{} MPI ranks for {} starts: {} ranks ran none", ranks, starts.size(), ranks - starts.size()));
  std::vector<double> x;
  std::string message;
  for (size_t s = 0; s < starts.size(); ++s) {
    const CalibrationStart& r = runs[s].result;
    out.residual_evaluations += runs[s].evaluations;
    out.jacobian_fallbacks += runs[s].fallbacks;
    out.one_sided_columns += runs[s].one_sided;
    out.starts.push_back(r);
    // The lowest cost wins, converged or not: a converged start at a higher cost is a worse model,
    // and an unconverged one is continued from its values (calibrate --restart-from).
    const CalibrationStart& best = out.starts[out.best];
    if (s == 0 || (r.evaluated && !best.evaluated) || (r.evaluated && r.final_cost < best.final_cost)) {
      out.best = s;
      x = runs[s].x;
      message = runs[s].message;
      out.termination = runs[s].brief;
      out.history = runs[s].history;
    }
  }
  const CalibrationStart& chosen = out.starts[out.best];
  out.initial_cost = out.starts.front().initial_cost;
  out.final_cost = chosen.final_cost;
  out.converged = chosen.converged;
  if (!out.converged) out.warnings.push_back("the fit did not converge: " + message);
  for (size_t s = 0; s < out.starts.size(); ++s)
    if (!out.starts[s].evaluated)
      out.warnings.push_back(
          fmt::format("start {} could not be evaluated at its start values (the model failed "
                      "there: {}): it took no step",
                      s + 1, runs[s].message));
    else if (!chosen.converged && out.starts[s].converged)
      out.warnings.push_back(fmt::format(
          "start {} converged, at a higher cost ({:.6g}) than the reported start {} ({:.6g}), which did not: "
          "continue the reported start (calibrate --restart-from restart.toml, or a higher max_iterations)",
          s + 1, out.starts[s].final_cost, out.best + 1, chosen.final_cost));
    else if (s != out.best && runs[s].failed)
      out.warnings.push_back(
          fmt::format("start {} stopped after {} iterations at cost {:.6g}: the model could not be run where the fit "
                      "needed it ({}); its minimum is unknown",
                      s + 1, out.starts[s].iterations, out.starts[s].final_cost, runs[s].message));
  const double dof = static_cast<double>(residuals) - static_cast<double>(n);
  out.reduced_chi_square = dof > 0 ? 2.0 * out.final_cost / dof : NAN;
  if (starts.size() > 1) warn_other_minima(out, n);
  ceres::Problem problem;
  // At the chosen optimum, for the covariance.
  build(x, problem, &out.residual_evaluations, &out.jacobian_fallbacks, &out.one_sided_columns);
  out.values.resize(n);
  out.values = values_at(cal, x.data());
  add_covariance(problem, x, cal, out);
  for (size_t i = 0; i < n; ++i) {
    const CalibrationParameter& q = cal.parameters[i];
    const double span = q.to_fit(q.upper) - q.to_fit(q.lower);
    if (std::abs(x[i] - q.to_fit(q.lower)) < 1e-3 * span || std::abs(x[i] - q.to_fit(q.upper)) < 1e-3 * span)
      out.warnings.push_back(fmt::format("'{}' ended on a bound ({:.6g}): the optimum may lie outside the stated range",
                                         cal.parameters[i].path, out.values[i]));
  }
  return out;
}

}  // namespace bb
