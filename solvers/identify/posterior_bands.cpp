#include "identify/posterior_bands.hpp"

#include <chrono>
#include <cmath>
#include <random>

#include "identify/ensemble_sampler.hpp"

namespace bb {

PosteriorSummary sample_posterior(const CalibrationSpec& spec, const CalibrationOutcome& o, const FitEvaluator& fitted,
                                  const std::function<std::vector<FitPoint>(const std::vector<double>&)>& predict,
                                  std::vector<FitPoint>& points) {
  const auto t0 = std::chrono::steady_clock::now();
  const CalibrationSpec::Sampler& s = *spec.sampler;
  const auto n = static_cast<Eigen::Index>(spec.parameters.size());
  const double temper = std::max(1.0, std::isfinite(o.reduced_chi_square) ? o.reduced_chi_square : 1.0);
  const auto values_of = [&](const Eigen::VectorXd& x) {
    std::vector<double> v(static_cast<size_t>(n));
    for (Eigen::Index j = 0; j < n; ++j) v[static_cast<size_t>(j)] = spec.parameters[static_cast<size_t>(j)].from_fit(x[j]);
    return v;
  };
  const auto log_posterior = [&](const Eigen::VectorXd& x) -> double {
    const std::vector<double> v = values_of(x);
    for (Eigen::Index j = 0; j < n; ++j) {
      const CalibrationParameter& p = spec.parameters[static_cast<size_t>(j)];
      if (!(v[static_cast<size_t>(j)] >= p.lower && v[static_cast<size_t>(j)] <= p.upper)) return -INFINITY;
    }
    try {
      double cost = 0.0;
      for (const FitPoint& p : fitted(v, false)) {
        if (!std::isfinite(p.computed)) return -INFINITY;
        cost += 0.5 * p.residual() * p.residual();
      }
      return -cost / temper;
    } catch (const std::exception&) {
      return -INFINITY;  // the model cannot be run there
    }
  };
  const int walkers = s.walkers > 0 ? s.walkers : static_cast<int>(4 * n + (4 * n) % 2);
  Eigen::VectorXd centre(n), radius(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const CalibrationParameter& p = spec.parameters[static_cast<size_t>(j)];
    const double v = o.values[static_cast<size_t>(j)], sd = o.std_devs[static_cast<size_t>(j)];
    centre[j] = p.to_fit(v);
    radius[j] = std::isfinite(sd) && sd > 0.0 ? 0.1 * sd / p.value_per_fit(v) : 1e-3;
  }
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd start(walkers, n);
  for (int w = 0; w < walkers; ++w)
    for (int attempt = 0;; ++attempt) {
      for (Eigen::Index j = 0; j < n; ++j) start(w, j) = centre[j] + radius[j] * normal(rng) / (1.0 + attempt);
      if (std::isfinite(log_posterior(start.row(w).transpose())) || attempt > 20) break;
    }
  SamplerOptions options;
  options.steps = s.steps;
  options.burn_in = s.burn_in;
  options.seed = s.seed;
  options.threads = spec.threads;
  const SamplerResult r = sample_ensemble(log_posterior, start, options);
  PosteriorSummary out;
  out.walkers = walkers;
  out.steps = s.steps;
  out.kept_steps = r.kept_steps;
  out.evaluations = r.evaluations;
  out.acceptance = r.acceptance;
  out.autocorrelation_steps = r.autocorrelation_steps;
  out.warning = r.warning;
  // Parameter moments in their units, and every point's spread over evenly spaced kept samples.
  Eigen::MatrixXd values(r.chain.rows(), n);
  for (Eigen::Index k = 0; k < r.chain.rows(); ++k) {
    const std::vector<double> v = values_of(r.chain.row(k).transpose());
    for (Eigen::Index j = 0; j < n; ++j) values(k, j) = v[static_cast<size_t>(j)];
  }
  const Eigen::RowVectorXd mean = values.colwise().mean();
  for (Eigen::Index j = 0; j < n; ++j) {
    out.mean.push_back(mean[j]);
    out.std_dev.push_back(std::sqrt((values.col(j).array() - mean[j]).square().sum() /
                                    static_cast<double>(std::max<Eigen::Index>(1, values.rows() - 1))));
  }
  const Eigen::Index picks = std::min<Eigen::Index>(s.predictions, r.chain.rows());
  std::vector<double> sum(points.size(), 0.0), sum2(points.size(), 0.0);
  int used = 0;
  for (Eigen::Index i = 0; i < picks; ++i) {
    const Eigen::Index k = (i * r.chain.rows()) / picks;
    std::vector<FitPoint> at;
    try {
      at = predict(values_of(r.chain.row(k).transpose()));
    } catch (const std::exception&) {
      continue;
    }
    if (at.size() != points.size()) continue;
    ++used;
    for (size_t q = 0; q < at.size(); ++q) sum[q] += at[q].computed, sum2[q] += at[q].computed * at[q].computed;
  }
  out.predictions = used;
  if (used > 1)
    for (size_t q = 0; q < points.size(); ++q) {
      const double m = sum[q] / used;
      points[q].sampled_band = std::sqrt(std::max(0.0, (sum2[q] - used * m * m) / (used - 1)));
    }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace bb
