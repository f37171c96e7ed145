#include "identify/fit_identifiability.hpp"

#include <Eigen/SVD>
#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "linalg/dense_eigen.hpp"

namespace bb {
namespace {

// How a fit value reads in a warning: log(p), or p / (upper - lower).
std::string fit_name(const CalibrationParameter& q) {
  return q.scale == CalibrationParameter::Scale::log ? fmt::format("log({})", q.path)
                                                     : fmt::format("{} / {:.3g}", q.path, q.upper - q.lower);
}

// Relative to the largest singular value of the Jacobian (fit values), the size below which a
// direction of the parameters is not determined by the fitted points: the pseudo-inverse drops it,
// which would report it with a variance of zero.
constexpr double kUnidentified = 1e-8;

// Of (J^T J)'s eigenvalues, those below this share of the largest are dropped from its pseudo-inverse
// (Ceres's default min_reciprocal_condition_number, as its DENSE_SVD covariance truncates).
constexpr double kMinReciprocalCondition = 1e-14;

// The Jacobian of the residuals in fit values at the problem's values (robust loss applied);
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
// Jacobian in fit values (scale free) and its SVD: a zero column is a parameter without effect,
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
    std::vector<std::string> terms;  // the weak direction, in fit values
    for (Eigen::Index i = 0; i < svd.matrixV().rows(); ++i)
      if (const double c = svd.matrixV()(i, k); std::abs(c) > 0.2 && !unidentified[static_cast<size_t>(i)])
        terms.push_back(fmt::format("{:+.2f} {}", c, fit_name(cal.parameters[static_cast<size_t>(i)])));
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
// standard deviations from the optimum x (fit values), clamped to the bounds: four model runs.
void profile_weakest_direction(ceres::Problem& problem, std::vector<double>& x, const Eigen::MatrixXd& c,
                               const std::vector<bool>& unidentified, const CalibrationSpec& cal,
                               CalibrationOutcome& out) {
  const auto n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd kept = c;
  for (Eigen::Index i = 0; i < n; ++i)
    if (unidentified[static_cast<size_t>(i)]) kept.row(i).setZero(), kept.col(i).setZero();
  const DenseEigen<double> eig = symmetric_eigen(kept);
  if (!eig.ok || !(eig.values(n - 1) > 0.0)) return;
  const Eigen::VectorXd v = eig.vectors.col(n - 1);
  const double sigma = std::sqrt(eig.values(n - 1));
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
      const CalibrationParameter& q = cal.parameters[k];
      x[k] = std::clamp(optimum[k] + t * sigma * v(i), q.to_fit(q.lower), q.to_fit(q.upper));
      pt.values.push_back(q.from_fit(x[k]));
    }
    double cost = 0.0;
    if (problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr)) pt.rise = cost - cost0;
    out.weakest_profile.push_back(pt);
  }
  x = optimum;
  double flattest = INFINITY, steepest = 0.0, steepest_t = 0.0;
  for (const auto& pt : out.weakest_profile) {
    if (!std::isfinite(pt.rise)) continue;
    if (std::abs(pt.t) == 2.0) flattest = std::min(flattest, pt.rise / pt.predicted);
    if (pt.rise / pt.predicted > steepest) steepest = pt.rise / pt.predicted, steepest_t = pt.t;
  }
  // Far steeper than the quadratic (200-2500x seen on a rig's joint, issue 68): the Jacobian at the
  // optimum does not describe the cost a standard deviation away, in either sense.
  if (steepest > 10.0)
    out.warnings.push_back(fmt::format(
        "along the weakest direction the cost rises {:.3g} times what the covariance predicts at {:+g} standard "
        "deviations: the cost is far from quadratic there, so the standard deviations are not to be trusted along it "
        "(report: weakest direction)",
        steepest, steepest_t));
  if (flattest < 0.25)
    out.warnings.push_back(fmt::format(
        "along the weakest direction the cost rises by only {:.2g} of what the covariance predicts at 2 standard "
        "deviations: the standard deviations understate the uncertainty there (report: weakest direction)",
        flattest));
}

}  // namespace

// The covariance at the optimum x (fit values) as standard deviations and correlations, with the
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
    const CalibrationParameter& q = cal.parameters[i];
    const double sigma_fit = std::sqrt(std::max(c(ii, ii), 0.0));
    if (!unidentified[i]) out.std_devs[i] = q.value_per_fit(out.values[i]) * sigma_fit;
    // A +-1 sigma interval (in fit values) wider than the bounds: only the bounds hold it.
    if (!unidentified[i] && 2.0 * sigma_fit > q.to_fit(q.upper) - q.to_fit(q.lower))
      out.warnings.push_back(
          fmt::format("'{}' is not determined by the data within its bounds: its 1-sigma interval ({}) is wider than "
                      "[{:.6g}, {:.6g}]; its value is the bounds' and the start's, not the data's",
                      q.path,
                      q.scale == CalibrationParameter::Scale::log ? fmt::format("x/ {:.3g}", std::exp(sigma_fit))
                                                                  : fmt::format("+- {:.3g}", out.std_devs[i]),
                      q.lower, q.upper));
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
    for (size_t i = 0; i < n; ++i) {  // within 5 % (log) or 5 % of the range (linear)
      const CalibrationParameter& q = out.spec.parameters[i];
      same = same && std::abs(q.to_fit(out.starts[s].values[i]) - q.to_fit(chosen.values[i])) < 0.05;
    }
    if (!same)
      out.warnings.push_back(fmt::format(
          "start {} reaches a cost ({:.6g}) within the 95 % confidence region of the best ({:.6g}) at other "
          "values: the minimum is not unique",
          s + 1, out.starts[s].final_cost, chosen.final_cost));
  }
}

}  // namespace bb
