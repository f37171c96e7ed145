#include "identify/calibrate_case.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <variant>

#include "analysis/case_results.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// Replaces the number at `path`; it must exist (a cross-check case must hold every fitted value).
void set_number(toml::table& root, const std::string& path, double value) {
  toml::node* n = node_at_path(root, path);
  if (!n || !n->is_number()) throw InputError(fmt::format("calibration path '{}' is not a number in the case", path));
  if (toml::value<double>* f = n->as_floating_point()) {
    *f = value;
    return;
  }
  const size_t dot = path.rfind('.');  // an integer: replaced by a float in its parent table
  toml::node* parent = dot == std::string::npos ? &root : node_at_path(root, path.substr(0, dot));
  if (!parent || !parent->is_table()) throw InputError(fmt::format("calibration path '{}' is inside an array of numbers", path));
  parent->as_table()->insert_or_assign(path.substr(dot == std::string::npos ? 0 : dot + 1), value);
}

toml::table with_values(const toml::table& base, const CalibrationSpec& cal, const std::vector<double>& values) {
  toml::table t = base;
  for (size_t i = 0; i < values.size(); ++i) set_number(t, cal.parameters[i].path, values[i]);
  return t;
}

std::vector<std::string> parameter_paths(const CalibrationSpec& cal) {
  std::vector<std::string> paths;
  for (const CalibrationParameter& p : cal.parameters) paths.push_back(p.path);
  return paths;
}

// The fitted points of a case table with the given parameter values, and the tables of its curves;
// with `gradients`, frf points carry d r / d log p from the tables' sensitivity columns.
std::vector<FitPoint> fitted_points(const toml::table& base, const fs::path& file, const CalibrationSpec& cal,
                                    const std::vector<double>& values, ResultTables* curves = nullptr, bool gradients = false) {
  const CaseSpec spec = parse_case_table(with_values(base, cal, values), file);
  const Model model = build_model(spec);
  const CaseResults results = compute_case_results(spec, model);
  std::vector<FitPoint> points;
  for (const CheckSpec& c : spec.checks) {
    if (std::find(cal.fit_checks.begin(), cal.fit_checks.end(), c.name) == cal.fit_checks.end()) continue;
    const auto e = check_points(evaluate_check(c, results.tables), cal);
    points.insert(points.end(), e.begin(), e.end());
  }
  for (const CalibrationData& d : cal.data) {
    const auto e = data_points(d, results.tables, gradients ? parameter_paths(cal) : std::vector<std::string>{});
    points.insert(points.end(), e.begin(), e.end());
    if (curves) curves->insert_or_assign(d.table, results.tables.at(d.table));
  }
  return points;
}

// r_k = (computed_k - measured_k) / sigma_k: the misfit in units of the stated uncertainty.
struct CaseResidual {
  const toml::table* base;
  fs::path file;
  const CalibrationSpec* cal;
  int* evaluations;
  bool operator()(double const* const* log_values, double* residuals) const {
    std::vector<double> values(cal->parameters.size());
    for (size_t i = 0; i < values.size(); ++i) values[i] = std::exp(log_values[0][i]);
    try {
      const auto points = fitted_points(*base, file, *cal, values);
      ++*evaluations;
      for (const FitPoint& p : points)
        if (!std::isfinite(p.computed)) return false;  // a peak or mode not found there: Ceres shrinks the step
      for (size_t k = 0; k < points.size(); ++k) residuals[k] = points[k].residual();
      return true;
    } catch (const std::exception&) {
      return false;  // an impossible geometry or a failed solve: Ceres shrinks the step
    }
  }
};

// The same residuals with the Jacobian from the model's own sensitivities: one model run per
// evaluation instead of 2 n + 1 (the parameters are log values: J_kj = p_j dr_k/dp_j).
class AnalyticCaseResidual : public ceres::CostFunction {
 public:
  AnalyticCaseResidual(const toml::table* base, fs::path file, const CalibrationSpec* cal, int* evaluations, int residuals)
      : base_(base), file_(std::move(file)), cal_(cal), evaluations_(evaluations) {
    set_num_residuals(residuals);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(cal->parameters.size()));
  }

  bool Evaluate(double const* const* log_values, double* residuals, double** jacobians) const override {
    const size_t n = cal_->parameters.size();
    std::vector<double> values(n);
    for (size_t i = 0; i < n; ++i) values[i] = std::exp(log_values[0][i]);
    try {
      const auto points = fitted_points(*base_, file_, *cal_, values, nullptr, true);
      ++*evaluations_;
      if (points.size() != static_cast<size_t>(num_residuals())) return false;
      for (size_t k = 0; k < points.size(); ++k) {
        const FitPoint& p = points[k];
        if (!std::isfinite(p.computed)) return false;  // as CaseResidual: Ceres shrinks the step
        residuals[k] = p.residual();
        if (!jacobians || !jacobians[0]) continue;
        if (p.gradient.size() != n) return false;
        for (size_t j = 0; j < n; ++j) {
          if (!std::isfinite(p.gradient[j])) return false;  // next to a grid point that has no derivative
          jacobians[0][k * n + j] = p.gradient[j];
        }
      }
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }

 private:
  const toml::table* base_;
  fs::path file_;
  const CalibrationSpec* cal_;
  int* evaluations_;
};

// The case table asking the hbm analysis for the sensitivities to every parameter, when analytic
// derivatives can serve the whole fit: derivatives = "auto", only frf data, and the analysis
// accepts every path (parse_hbm checks which ones it differentiates). Otherwise the reason why not.
std::variant<toml::table, std::string> analytic_case(const toml::table& base, const fs::path& file, const CalibrationSpec& cal) {
  if (cal.derivatives != "auto") return std::string("derivatives = \"numeric\"");
  if (!cal.fit_checks.empty()) return std::string("fitted checks have no derivatives");
  for (const CalibrationData& d : cal.data)
    if (d.data.kind != DataKind::frf) return fmt::format("data '{}' is not frf data", d.name);
  toml::table t = base;
  toml::table* analysis = t["analysis"].as_table();
  if (!analysis || analysis->get("type") == nullptr || analysis->get("type")->value<std::string>() != "hbm")
    return std::string("the analysis is not hbm");
  std::vector<std::string> paths;
  if (const toml::array* given = analysis->get_as<toml::array>("sensitivities"))
    for (const toml::node& n : *given)
      if (const auto v = n.value<std::string>()) paths.push_back(*v);
  for (const std::string& p : parameter_paths(cal))
    if (std::find(paths.begin(), paths.end(), p) == paths.end()) paths.push_back(p);
  toml::array list;
  for (const std::string& p : paths) list.push_back(p);
  analysis->insert_or_assign("sensitivities", std::move(list));
  try {
    (void)parse_case_table(t, file);
  } catch (const InputError& e) {
    return fmt::format("the analysis has no sensitivities for these parameters ({})", e.what());
  }
  return t;
}

class Progress : public ceres::IterationCallback {
 public:
  Progress(bool show, CalibrationOutcome& out, int start, int starts) : show_(show), out_(out), start_(start), starts_(starts) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    out_.history.emplace_back(s.iteration, s.cost);
    if (show_)
      std::fprintf(stderr, "\r  calibration: start %d of %d, iteration %3d  cost %.6e  |gradient| %.3e  step %s   ", start_, starts_,
                   s.iteration, s.cost, s.gradient_max_norm, s.step_is_successful ? "accepted" : "rejected");
    return ceres::SOLVER_CONTINUE;
  }

 private:
  bool show_;
  CalibrationOutcome& out_;
  int start_, starts_;
};

}  // namespace

bool CalibrationOutcome::cross_check_passed() const {
  return std::all_of(cross_check.begin(), cross_check.end(), [](const CheckEntry& e) { return e.pass; });
}

CalibrationOutcome calibrate_case(const fs::path& case_file, bool show_progress) {
  const toml::table base = read_case_table(case_file);
  const CaseSpec spec = parse_case_table(base, case_file);
  auto cal = parse_calibration(base, case_file, spec);
  if (!cal) throw InputError(fmt::format("{}: no [calibration] section", case_file.string()));
  CalibrationOutcome out;
  out.spec = *cal;
  const size_t n = cal->parameters.size();
  std::vector<double> start(n);
  for (size_t i = 0; i < n; ++i) start[i] = cal->parameters[i].start;
  const auto analytic_base = analytic_case(base, case_file, *cal);
  const toml::table* sensitivity_base = std::get_if<toml::table>(&analytic_base);
  out.before = fitted_points(sensitivity_base ? *sensitivity_base : base, case_file, *cal, start, &out.curves_before, sensitivity_base != nullptr);
  for (const FitPoint& p : out.before)
    if (!(p.sigma > 0.0)) throw InputError(fmt::format("{}: fitted entry '{}' has a zero reference or uncertainty", cal->at.where(), p.label));
  std::string numeric_reason = sensitivity_base ? "" : std::get<std::string>(analytic_base);
  if (sensitivity_base)
    for (const FitPoint& p : out.before)
      if (p.gradient.size() != n || !std::all_of(p.gradient.begin(), p.gradient.end(), [](double g) { return std::isfinite(g); }))
        numeric_reason = fmt::format("no finite sensitivities for '{}' of '{}' at the start", p.label, p.set);
  const bool analytic = numeric_reason.empty();
  out.derivatives = analytic ? "analytic (implicit function theorem, hbm/sensitivity.hpp)"
                             : fmt::format("central differences, relative step {:g} ({})", cal->derivative_step,
                                           cal->derivatives == "numeric" ? "as asked" : numeric_reason);

  // Start points in log space: the case's values, then a Latin hypercube within the bounds.
  std::vector<std::vector<double>> starts{start};
  if (cal->starts > 1) {
    std::mt19937 rng(cal->seed);
    const int m = cal->starts - 1;
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
        const double lo = std::log(cal->parameters[i].lower), hi = std::log(cal->parameters[i].upper);
        p[i] = std::exp(lo + (hi - lo) * (strata[i][static_cast<size_t>(k)] + unit(rng)) / m);
      }
      starts.push_back(p);
    }
  }
  ceres::NumericDiffOptions diff;
  diff.relative_step_size = cal->derivative_step;  // default 1e-4: above the eigensolver's 1e-10 noise, below the model's curvature
  // The problem for log-values x (Ceres keeps a pointer to x: one problem per start).
  const auto build = [&](std::vector<double>& x, ceres::Problem& problem) {
    ceres::CostFunction* cost = nullptr;
    if (analytic) {
      cost = new AnalyticCaseResidual(sensitivity_base, case_file, &*cal, &out.residual_evaluations, static_cast<int>(out.before.size()));
    } else {
      auto* numeric = new ceres::DynamicNumericDiffCostFunction<CaseResidual, ceres::CENTRAL>(
          new CaseResidual{&base, case_file, &*cal, &out.residual_evaluations}, ceres::TAKE_OWNERSHIP, diff);
      numeric->AddParameterBlock(static_cast<int>(n));
      numeric->SetNumResiduals(static_cast<int>(out.before.size()));
      cost = numeric;
    }
    ceres::LossFunction* loss = nullptr;
    if (cal->loss == "huber") loss = new ceres::HuberLoss(cal->loss_scale);
    if (cal->loss == "cauchy") loss = new ceres::CauchyLoss(cal->loss_scale);
    problem.AddResidualBlock(cost, loss, x.data());
    for (size_t i = 0; i < n; ++i) {
      problem.SetParameterLowerBound(x.data(), static_cast<int>(i), std::log(cal->parameters[i].lower));
      problem.SetParameterUpperBound(x.data(), static_cast<int>(i), std::log(cal->parameters[i].upper));
    }
  };
  ceres::Solver::Options options;
  options.max_num_iterations = cal->max_iterations;
  options.linear_solver_type = ceres::DENSE_QR;
  options.function_tolerance = cal->function_tolerance;
  options.parameter_tolerance = 1e-8;
  options.update_state_every_iteration = true;
  std::vector<double> x;
  std::string message;
  std::vector<std::pair<int, double>> best_history;
  for (size_t s = 0; s < starts.size(); ++s) {
    std::vector<double> xs(n);
    for (size_t i = 0; i < n; ++i) xs[i] = std::log(starts[s][i]);
    ceres::Problem problem;
    build(xs, problem);
    CalibrationOutcome trace;
    Progress progress(show_progress && isatty(STDERR_FILENO), trace, static_cast<int>(s + 1), static_cast<int>(starts.size()));
    ceres::Solver::Options o = options;
    o.callbacks.push_back(&progress);
    ceres::Solver::Summary summary;
    ceres::Solve(o, &problem, &summary);
    if (show_progress && isatty(STDERR_FILENO)) std::fputc('\n', stderr);
    CalibrationStart r;
    r.start = starts[s];
    for (double v : xs) r.values.push_back(std::exp(v));
    r.initial_cost = summary.initial_cost;
    r.final_cost = summary.final_cost;
    r.iterations = static_cast<int>(summary.iterations.size());
    r.converged = summary.termination_type == ceres::CONVERGENCE;
    out.starts.push_back(r);
    if (s == 0 || (r.converged && (!out.starts[out.best].converged || r.final_cost < out.starts[out.best].final_cost)) ||
        (!out.starts[out.best].converged && r.final_cost < out.starts[out.best].final_cost)) {
      out.best = s;
      x = xs;
      message = summary.message;
      out.termination = summary.BriefReport();
      best_history = trace.history;
    }
  }
  const CalibrationStart& chosen = out.starts[out.best];
  out.history = best_history;
  out.initial_cost = out.starts.front().initial_cost;
  out.final_cost = chosen.final_cost;
  out.converged = chosen.converged;
  if (!out.converged) out.warnings.push_back("the fit did not converge: " + message);
  // Birge ratio: when the fit is worse than the stated uncertainties allow (reduced chi-square
  // above 1, e.g. outliers or an imperfect model), the covariance is scaled up by it.
  const double dof = static_cast<double>(out.before.size()) - static_cast<double>(n);
  out.reduced_chi_square = dof > 0 ? 2.0 * out.final_cost / dof : NAN;
  // Another start's minimum counts as "as good" when it lies inside the 95 % joint confidence
  // region of the best one: delta chi-square (scaled like the covariance) below the chi-square
  // quantile for n parameters.
  const double chi2_95[] = {3.84, 5.99, 7.81, 9.49, 11.07, 12.59, 14.07, 15.51, 16.92, 18.31};
  const double quantile = n <= 10 ? chi2_95[n - 1] : static_cast<double>(n) + 2.0 * std::sqrt(2.0 * static_cast<double>(n));
  const double scale = std::isfinite(out.reduced_chi_square) ? std::max(1.0, out.reduced_chi_square) : 1.0;
  if (starts.size() > 1)
    for (size_t s = 0; s < out.starts.size(); ++s)
      if (s != out.best && out.starts[s].converged && 2.0 * (out.starts[s].final_cost - chosen.final_cost) / scale < quantile) {
        bool same = true;
        for (size_t i = 0; i < n; ++i) same = same && std::abs(std::log(out.starts[s].values[i] / chosen.values[i])) < 0.05;
        if (!same)
          out.warnings.push_back(fmt::format("start {} reaches a cost ({:.6g}) within the 95 % confidence region of the best ({:.6g}) at other "
                                             "values: the minimum is not unique", s + 1, out.starts[s].final_cost, chosen.final_cost));
      }
  ceres::Problem problem;
  build(x, problem);  // at the chosen optimum, for the covariance
  out.values.resize(n);
  for (size_t i = 0; i < n; ++i) out.values[i] = std::exp(x[i]);
  out.std_devs.assign(n, NAN);
  ceres::Covariance::Options cov_options;
  cov_options.algorithm_type = ceres::DENSE_SVD;
  cov_options.null_space_rank = -1;  // report rank deficiency instead of failing
  ceres::Covariance covariance(cov_options);
  std::vector<std::pair<const double*, const double*>> blocks{{x.data(), x.data()}};
  if (covariance.Compute(blocks, &problem)) {
    Eigen::MatrixXd c(n, n);
    covariance.GetCovarianceBlock(x.data(), x.data(), c.data());
    out.correlation.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    if (out.reduced_chi_square > 1.0) c *= out.reduced_chi_square;
    for (size_t i = 0; i < n; ++i) {
      const auto ii = static_cast<Eigen::Index>(i);
      out.std_devs[i] = out.values[i] * std::sqrt(std::max(c(ii, ii), 0.0));  // log-space sigma -> value sigma
      for (size_t j = 0; j < n; ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        out.correlation(ii, jj) = c(ii, jj) / std::sqrt(c(ii, ii) * c(jj, jj));
        if (j > i && std::abs(out.correlation(ii, jj)) > 0.95)
          out.warnings.push_back(fmt::format("'{}' and '{}' correlate at {:.3f}: the data cannot separate them",
                                             cal->parameters[i].path, cal->parameters[j].path, out.correlation(ii, jj)));
      }
    }
  } else {
    out.warnings.push_back("the covariance could not be computed: the problem is rank deficient at the optimum");
  }
  for (size_t i = 0; i < n; ++i) {
    const double span = std::log(cal->parameters[i].upper / cal->parameters[i].lower);
    if (std::abs(x[i] - std::log(cal->parameters[i].lower)) < 1e-3 * span || std::abs(x[i] - std::log(cal->parameters[i].upper)) < 1e-3 * span)
      out.warnings.push_back(fmt::format("'{}' ended on a bound ({:.6g}): the optimum may lie outside the stated range",
                                         cal->parameters[i].path, out.values[i]));
  }
  out.after = fitted_points(base, case_file, *cal, out.values, &out.curves_after);
  out.calibrated = with_values(base, *cal, out.values);
  if (!cal->cross_check.empty()) {
    // The same parameter paths in an independent model (e.g. Newmark instead of the harmonic balance).
    const auto t0 = std::chrono::steady_clock::now();
    const toml::table cross_base = read_case_table(cal->cross_check);
    const CaseSpec cross = parse_case_table(with_values(cross_base, *cal, out.values), cal->cross_check);
    const CaseResults results = compute_case_results(cross, build_model(cross));
    for (const CheckSpec& c : cross.checks) {
      const auto e = evaluate_check(c, results.tables);
      out.cross_check.insert(out.cross_check.end(), e.begin(), e.end());
    }
    out.cross_check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!out.cross_check_passed())
      out.warnings.push_back(fmt::format("the cross-check {} fails with the identified values", cal->cross_check.string()));
  }
  return out;
}

}  // namespace bb
