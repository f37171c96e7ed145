#include "identify/least_squares_fit.hpp"

#include <Eigen/SVD>
#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <random>

#include "common/parallel_indices.hpp"
#include "identify/central_differences.hpp"

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

// The residuals r_k = (computed_k - measured_k) / sigma_k (the misfit in units of the stated
// uncertainty, through the robust loss) at log values, for central differences; several may run at
// once (the Jacobian's columns on workers), hence the atomic count.
struct NumericResidual {
  const FitEvaluator* evaluate;
  size_t parameters;
  int* evaluations;
  RobustLoss loss;
  bool operator()(const std::vector<double>& log_values, double* residuals) const {
    std::vector<double> values(parameters);
    for (size_t i = 0; i < values.size(); ++i) values[i] = std::exp(log_values[i]);
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
// evaluation instead of 2 n + 1 (the parameters are log values: J_kj = p_j dr_k/dp_j). Where a
// point has no derivative (a peak on a corner of its curve, a singular Jacobian), that evaluation's
// Jacobian is taken by central differences instead, and counted.
class AnalyticResidual : public ceres::CostFunction {
 public:
  AnalyticResidual(const FitEvaluator* evaluate, size_t parameters, int* evaluations, int residuals,
                   double derivative_step, size_t workers, int* fallbacks, RobustLoss loss)
      : evaluate_(evaluate),
        evaluations_(evaluations),
        fallbacks_(fallbacks),
        loss_(loss),
        differences_(NumericResidual{evaluate, parameters, evaluations, loss}, static_cast<int>(parameters), residuals,
                     derivative_step, workers) {
    set_num_residuals(residuals);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(parameters));
  }

  bool Evaluate(double const* const* log_values, double* residuals, double** jacobians) const override {
    const size_t n = static_cast<size_t>(parameter_block_sizes()[0]);
    std::vector<double> values(n);
    for (size_t i = 0; i < n; ++i) values[i] = std::exp(log_values[0][i]);
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
        differentiable = differentiable && p.gradient.size() == n &&
                         std::all_of(p.gradient.begin(), p.gradient.end(), [](double g) { return std::isfinite(g); });
        for (size_t j = 0; j < n && differentiable; ++j) jacobians[0][k * n + j] = slope * p.gradient[j];
      }
      if (differentiable) return true;
      ++*fallbacks_;
      return differences_.Evaluate(log_values, residuals, jacobians);
    } catch (const std::exception&) {
      return false;
    }
  }

 private:
  const FitEvaluator* evaluate_;
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

// The spec's values, then starts - 1 points of a Latin hypercube in log space within the bounds.
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
      const double lo = std::log(cal.parameters[i].lower), hi = std::log(cal.parameters[i].upper);
      p[i] = std::exp(lo + (hi - lo) * (strata[i][static_cast<size_t>(k)] + unit(rng)) / m);
    }
    starts.push_back(p);
  }
  return starts;
}

// Relative to the largest singular value of the Jacobian (log parameters), the size below which a
// direction of the parameters is not determined by the fitted points: the pseudo-inverse drops it,
// which would report it with a variance of zero.
constexpr double kUnidentified = 1e-8;

// Of (J^T J)'s eigenvalues, those below this share of the largest are dropped from its pseudo-inverse
// (Ceres's default min_reciprocal_condition_number, as its DENSE_SVD covariance truncates).
constexpr double kMinReciprocalCondition = 1e-14;

// The Jacobian of the residuals in log parameters at the problem's values (robust loss applied);
// nullopt when it cannot be evaluated there.
std::optional<Eigen::MatrixXd> jacobian_at(ceres::Problem& problem) {
  ceres::CRSMatrix crs;
  if (!problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr, &crs)) return std::nullopt;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[static_cast<size_t>(r)]; k < crs.rows[static_cast<size_t>(r) + 1]; ++k)
      j(r, crs.cols[static_cast<size_t>(k)]) = crs.values[static_cast<size_t>(k)];
  return j;
}

// The parameters and combinations the fitted points do not determine at the optimum, from the
// Jacobian in log parameters (scale free) and its SVD: a zero column is a parameter without effect,
// a vanishing singular value a combination that trades off exactly. Returns the parameters not
// identified.
std::vector<bool> warn_unidentified(const Eigen::MatrixXd& j, const Eigen::JacobiSVD<Eigen::MatrixXd>& svd,
                                    const CalibrationSpec& cal, CalibrationOutcome& out) {
  const size_t n = cal.parameters.size();
  std::vector<bool> unidentified(n, false);
  const Eigen::VectorXd& sv = svd.singularValues();
  if (sv.size() == 0 || !(sv(0) > 0.0)) {
    out.warnings.push_back("no parameter has an effect on the fitted points at the optimum: nothing is identified");
    unidentified.assign(n, true);
    return unidentified;
  }
  for (size_t i = 0; i < n; ++i)
    if (j.col(static_cast<Eigen::Index>(i)).norm() <= kUnidentified * sv(0)) {
      unidentified[i] = true;
      out.warnings.push_back(
          fmt::format("'{}' has no effect on the fitted points at the optimum: it is not "
                      "identified (no standard deviation or correlation is given for it)",
                      cal.parameters[i].path));
    }
  for (Eigen::Index k = 0; k < sv.size(); ++k) {
    if (sv(k) > kUnidentified * sv(0)) continue;
    std::vector<std::string> terms;  // the weak direction, in log parameters
    for (Eigen::Index i = 0; i < svd.matrixV().rows(); ++i)
      if (const double c = svd.matrixV()(i, k); std::abs(c) > 0.2 && !unidentified[static_cast<size_t>(i)])
        terms.push_back(fmt::format("{:+.2f} log({})", c, cal.parameters[static_cast<size_t>(i)].path));
    if (terms.size() < 2) continue;  // a single parameter: named above
    std::string combination;
    for (const std::string& t : terms) combination += (combination.empty() ? "" : " ") + t;
    out.warnings.push_back(
        fmt::format("the fitted points do not determine the combination {} (singular value "
                    "{:.2g} of the largest): these parameters trade off; hold one of them",
                    combination, sv(k) / sv(0)));
    for (Eigen::Index i = 0; i < svd.matrixV().rows(); ++i)
      if (std::abs(svd.matrixV()(i, k)) > 0.2) unidentified[static_cast<size_t>(i)] = true;
  }
  return unidentified;
}

// The cost along the covariance's weakest direction (the identified parameters only), t = -2, -1, 1, 2
// standard deviations from the optimum x (log values), clamped to the bounds: four model runs.
void profile_weakest_direction(ceres::Problem& problem, std::vector<double>& x, const Eigen::MatrixXd& c,
                               const std::vector<bool>& unidentified, const CalibrationSpec& cal,
                               CalibrationOutcome& out) {
  const auto n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd kept = c;
  for (Eigen::Index i = 0; i < n; ++i)
    if (unidentified[static_cast<size_t>(i)]) kept.row(i).setZero(), kept.col(i).setZero();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(kept);
  if (eig.info() != Eigen::Success || !(eig.eigenvalues()(n - 1) > 0.0)) return;
  const Eigen::VectorXd v = eig.eigenvectors().col(n - 1);
  const double sigma = std::sqrt(eig.eigenvalues()(n - 1));
  const double scale = std::isfinite(out.reduced_chi_square) ? std::max(1.0, out.reduced_chi_square) : 1.0;
  const std::vector<double> optimum = x;
  double cost0 = 0.0;
  if (!problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost0, nullptr, nullptr, nullptr)) return;
  out.weakest_direction.assign(v.data(), v.data() + n);
  for (double t : {-2.0, -1.0, 1.0, 2.0}) {
    CalibrationOutcome::ProfilePoint pt;
    pt.t = t;
    pt.predicted = 0.5 * t * t * scale;
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto k = static_cast<size_t>(i);
      x[k] = std::clamp(optimum[k] + t * sigma * v(i), std::log(cal.parameters[k].lower),
                        std::log(cal.parameters[k].upper));
      pt.values.push_back(std::exp(x[k]));
    }
    double cost = 0.0;
    if (problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr)) pt.rise = cost - cost0;
    out.weakest_profile.push_back(pt);
  }
  x = optimum;
  double flattest = INFINITY;
  for (const auto& pt : out.weakest_profile)
    if (std::abs(pt.t) == 2.0 && std::isfinite(pt.rise)) flattest = std::min(flattest, pt.rise / pt.predicted);
  if (flattest < 0.25)
    out.warnings.push_back(fmt::format(
        "along the weakest direction the cost rises by only {:.2g} of what the covariance predicts at 2 standard "
        "deviations: the standard deviations understate the uncertainty there (report: weakest direction)",
        flattest));
}

// The covariance at the optimum x (log values) as standard deviations and correlations, with the
// Birge ratio: a fit worse than the stated uncertainties allow (reduced chi-square above 1, e.g.
// outliers or an imperfect model) scales the covariance up by it. A parameter the points do not
// determine gets none (NaN), rather than the zero the pseudo-inverse would give it. One Jacobian
// and one SVD serve both the identifiability warnings and the covariance.
void add_covariance(ceres::Problem& problem, std::vector<double>& x, const CalibrationSpec& cal,
                    CalibrationOutcome& out) {
  const size_t n = x.size();
  out.std_devs.assign(n, NAN);
  const std::optional<Eigen::MatrixXd> jacobian = jacobian_at(problem);
  if (!jacobian) {
    out.warnings.push_back("the covariance could not be computed: the model cannot be evaluated at the optimum");
    return;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(*jacobian, Eigen::ComputeFullV);
  const std::vector<bool> unidentified = warn_unidentified(*jacobian, svd, cal, out);
  // (J^T J)^+ = V S^-2 V^T over the directions kept.
  const Eigen::VectorXd& sv = svd.singularValues();
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (Eigen::Index k = 0; k < sv.size(); ++k)
    if (sv(k) > 0.0 && sv(k) * sv(k) >= kMinReciprocalCondition * sv(0) * sv(0))
      c += svd.matrixV().col(k) * svd.matrixV().col(k).transpose() / (sv(k) * sv(k));
  out.correlation.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  if (out.reduced_chi_square > 1.0) c *= out.reduced_chi_square;
  profile_weakest_direction(problem, x, c, unidentified, cal, out);
  for (size_t i = 0; i < n; ++i) {
    const auto ii = static_cast<Eigen::Index>(i);
    if (!unidentified[i]) out.std_devs[i] = out.values[i] * std::sqrt(std::max(c(ii, ii), 0.0));  // log -> value
    for (size_t j = 0; j < n; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      out.correlation(ii, jj) = unidentified[i] || unidentified[j] ? NAN : c(ii, jj) / std::sqrt(c(ii, ii) * c(jj, jj));
      if (j > i && std::abs(out.correlation(ii, jj)) > 0.95)
        out.warnings.push_back(fmt::format("'{}' and '{}' correlate at {:.3f}: the data cannot separate them",
                                           cal.parameters[i].path, cal.parameters[j].path, out.correlation(ii, jj)));
    }
  }
}

// Another start's minimum counts as "as good" when it lies inside the 95 % joint confidence region
// of the best one: delta chi-square (scaled like the covariance) below the chi-square quantile for
// n parameters.
void warn_other_minima(CalibrationOutcome& out, size_t n) {
  const CalibrationStart& chosen = out.starts[out.best];
  const double chi2_95[] = {3.84, 5.99, 7.81, 9.49, 11.07, 12.59, 14.07, 15.51, 16.92, 18.31};
  const double quantile =
      n <= 10 ? chi2_95[n - 1] : static_cast<double>(n) + 2.0 * std::sqrt(2.0 * static_cast<double>(n));
  const double scale = std::isfinite(out.reduced_chi_square) ? std::max(1.0, out.reduced_chi_square) : 1.0;
  for (size_t s = 0; s < out.starts.size(); ++s) {
    if (s == out.best || !out.starts[s].converged ||
        2.0 * (out.starts[s].final_cost - chosen.final_cost) / scale >= quantile)
      continue;
    bool same = true;
    for (size_t i = 0; i < n; ++i) same = same && std::abs(std::log(out.starts[s].values[i] / chosen.values[i])) < 0.05;
    if (!same)
      out.warnings.push_back(fmt::format(
          "start {} reaches a cost ({:.6g}) within the 95 % confidence region of the best ({:.6g}) at other "
          "values: the minimum is not unique",
          s + 1, out.starts[s].final_cost, chosen.final_cost));
  }
}

}  // namespace

CalibrationOutcome fit_parameters(const CalibrationSpec& cal, const FitEvaluator& evaluate, bool analytic,
                                  int residuals, const FitProgress& progress) {
  CalibrationOutcome out;
  out.spec = cal;
  const size_t n = cal.parameters.size();
  const std::vector<std::vector<double>> starts = start_points(cal);
  // The cores left to each start run its Jacobian's columns (a single start: all of them).
  const size_t at_once = worker_count(starts.size(), cal.threads);
  const size_t budget = worker_count(std::numeric_limits<size_t>::max(), cal.threads);
  const size_t column_workers = std::max<size_t>(1, budget / std::max<size_t>(1, at_once));
  // The problem for log-values x (Ceres keeps a pointer to x: one problem per start).
  const auto build = [&](std::vector<double>& x, ceres::Problem& problem, int* evaluations, int* fallbacks) {
    ceres::CostFunction* cost = nullptr;
    const RobustLoss loss = RobustLoss::of(cal);
    if (analytic) {
      cost = new AnalyticResidual(&evaluate, n, evaluations, residuals, cal.derivative_step, column_workers, fallbacks,
                                  loss);
    } else {
      // derivative_step (default 1e-4): above the eigensolver's 1e-10 noise, below the model's curvature.
      cost = new CentralDifferences(NumericResidual{&evaluate, n, evaluations, loss}, static_cast<int>(n), residuals,
                                    cal.derivative_step, column_workers);
    }
    problem.AddResidualBlock(cost, nullptr, x.data());
    for (size_t i = 0; i < n; ++i) {
      problem.SetParameterLowerBound(x.data(), static_cast<int>(i), std::log(cal.parameters[i].lower));
      problem.SetParameterUpperBound(x.data(), static_cast<int>(i), std::log(cal.parameters[i].upper));
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
  // Every start is its own problem: they run on `threads` workers, and the best is chosen in start
  // order afterwards, so the outcome is the serial one whatever the workers' timing.
  struct StartRun {
    CalibrationStart result;
    std::vector<double> x;
    std::string message, brief;
    std::vector<std::pair<int, double>> history;
    int evaluations = 0, fallbacks = 0;
  };
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
    for (size_t i = 0; i < n; ++i) run.x[i] = std::log(starts[s][i]);
    ceres::Problem problem;
    build(run.x, problem, &run.evaluations, &run.fallbacks);
    IterationTrace trace(locked_progress, run.history, static_cast<int>(s + 1), static_cast<int>(starts.size()),
                         cal.max_iterations);
    ceres::Solver::Options o = options;
    o.callbacks.push_back(&trace);
    ceres::Solver::Summary summary;
    ceres::Solve(o, &problem, &summary);
    CalibrationStart& r = run.result;
    r.start = starts[s];
    for (double v : run.x) r.values.push_back(std::exp(v));
    // Ceres gives -1 for the costs of a start whose values the model could not be run at.
    r.evaluated = summary.initial_cost >= 0.0;
    r.initial_cost = r.evaluated ? summary.initial_cost : NAN;
    r.final_cost = r.evaluated ? summary.final_cost : NAN;
    r.iterations = static_cast<int>(summary.iterations.size());
    r.converged = r.evaluated && summary.termination_type == ceres::CONVERGENCE;
    run.message = summary.message;
    run.brief = summary.BriefReport();
  };
  for_each_index(starts.size(), worker_count(starts.size(), cal.threads), run_start);
  std::vector<double> x;
  std::string message;
  for (size_t s = 0; s < starts.size(); ++s) {
    const CalibrationStart& r = runs[s].result;
    out.residual_evaluations += runs[s].evaluations;
    out.jacobian_fallbacks += runs[s].fallbacks;
    out.starts.push_back(r);
    const CalibrationStart& best = out.starts[out.best];
    if (s == 0 || (r.evaluated && !best.evaluated) ||
        (r.converged && (!best.converged || r.final_cost < best.final_cost)) ||
        (!best.converged && r.final_cost < best.final_cost)) {
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
  // A converged start is kept over unconverged ones; a cheaper unconverged start is said, since its
  // end is not a minimum and the true one may lie beyond it.
  for (size_t s = 0; s < out.starts.size(); ++s)
    if (!out.starts[s].evaluated)
      out.warnings.push_back(
          fmt::format("start {} could not be evaluated at its start values (the model failed "
                      "there: {}): it took no step",
                      s + 1, runs[s].message));
    else if (chosen.converged && !out.starts[s].converged && out.starts[s].final_cost < chosen.final_cost)
      out.warnings.push_back(fmt::format(
          "start {} reached a lower cost ({:.6g}) than the reported start {} ({:.6g}) but did not converge ({}): "
          "the best minimum may lie beyond it; raise max_iterations",
          s + 1, out.starts[s].final_cost, out.best + 1, chosen.final_cost, runs[s].message));
  const double dof = static_cast<double>(residuals) - static_cast<double>(n);
  out.reduced_chi_square = dof > 0 ? 2.0 * out.final_cost / dof : NAN;
  if (starts.size() > 1) warn_other_minima(out, n);
  ceres::Problem problem;
  build(x, problem, &out.residual_evaluations, &out.jacobian_fallbacks);  // at the chosen optimum, for the covariance
  out.values.resize(n);
  for (size_t i = 0; i < n; ++i) out.values[i] = std::exp(x[i]);
  add_covariance(problem, x, cal, out);
  for (size_t i = 0; i < n; ++i) {
    const double span = std::log(cal.parameters[i].upper / cal.parameters[i].lower);
    if (std::abs(x[i] - std::log(cal.parameters[i].lower)) < 1e-3 * span ||
        std::abs(x[i] - std::log(cal.parameters[i].upper)) < 1e-3 * span)
      out.warnings.push_back(fmt::format("'{}' ended on a bound ({:.6g}): the optimum may lie outside the stated range",
                                         cal.parameters[i].path, out.values[i]));
  }
  return out;
}

}  // namespace bb
