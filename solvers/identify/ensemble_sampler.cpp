#include "identify/ensemble_sampler.hpp"

#include <fmt/format.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "common/parallel_indices.hpp"

namespace bb {

double integrated_autocorrelation_time(const Eigen::VectorXd& series) {
  const Eigen::Index n = series.size();
  if (n < 4) return 1.0;
  const Eigen::VectorXd x = series.array() - series.mean();
  const double c0 = x.squaredNorm() / static_cast<double>(n);
  if (!(c0 > 0.0)) return 1.0;
  // tau = 1 + 2 sum rho(k), summed up to the first window M >= 5 tau(M) (Sokal 1997).
  double tau = 1.0;
  for (Eigen::Index k = 1; k < n; ++k) {
    const double rho = x.head(n - k).dot(x.tail(n - k)) / (static_cast<double>(n) * c0);
    tau += 2.0 * rho;
    if (static_cast<double>(k) >= 5.0 * tau) break;
  }
  return std::max(tau, 1.0);
}

SamplerResult sample_ensemble(const std::function<double(const Eigen::VectorXd&)>& log_posterior,
                              const Eigen::MatrixXd& start, const SamplerOptions& o) {
  const Eigen::Index walkers = start.rows(), dim = start.cols();
  if (walkers < 2 * dim || walkers % 2 != 0)
    throw std::invalid_argument(
        fmt::format("the ensemble sampler needs an even number of walkers, at least twice the {} parameters "
                    "(found {})",
                    dim, walkers));
  if (o.steps < 2 || !(o.stretch > 1.0)) throw std::invalid_argument("the sampler needs steps >= 2 and stretch > 1");
  const int burn = o.burn_in < 0 ? o.steps / 2 : std::min(o.burn_in, o.steps - 1);
  SamplerResult r;
  r.kept_steps = o.steps - burn;
  r.chain.resize(static_cast<Eigen::Index>(r.kept_steps) * walkers, dim);
  r.log_posterior.resize(r.chain.rows());
  Eigen::MatrixXd x = start;
  Eigen::VectorXd lp(walkers);
  const std::size_t workers = worker_count(static_cast<std::size_t>(walkers / 2), o.threads);
  for_each_index(static_cast<std::size_t>(walkers), workers,
                 [&](std::size_t w) { lp[static_cast<Eigen::Index>(w)] = log_posterior(start.row(static_cast<Eigen::Index>(w)).transpose()); });
  for (Eigen::Index w = 0; w < walkers; ++w)
    if (!std::isfinite(lp[w])) throw std::invalid_argument(fmt::format("walker {} starts outside the support", w + 1));
  std::vector<std::mt19937_64> streams;
  for (Eigen::Index w = 0; w < walkers; ++w) streams.emplace_back(o.seed * 1000003ULL + static_cast<unsigned>(w));
  long accepted = 0, moves = 0;
  const Eigen::Index half = walkers / 2;
  for (int step = 0; step < o.steps; ++step) {
    for (int part = 0; part < 2; ++part) {
      const Eigen::Index first = part * half, other = (1 - part) * half;
      std::vector<char> took(static_cast<std::size_t>(half), 0);
      // Each walker of this half moves toward a walker of the other half, held fixed meanwhile.
      for_each_index(static_cast<std::size_t>(half), workers, [&](std::size_t i) {
        const Eigen::Index w = first + static_cast<Eigen::Index>(i);
        std::mt19937_64& rng = streams[static_cast<std::size_t>(w)];
        const Eigen::Index j = other + std::uniform_int_distribution<Eigen::Index>(0, half - 1)(rng);
        const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        const double z = std::pow((o.stretch - 1.0) * u + 1.0, 2) / o.stretch;  // g(z) ~ 1 / sqrt(z) on [1/a, a]
        const Eigen::VectorXd y = x.row(j).transpose() + z * (x.row(w) - x.row(j)).transpose();
        const double lq = log_posterior(y);
        const double log_accept = static_cast<double>(dim - 1) * std::log(z) + lq - lp[w];
        if (std::isfinite(lq) && std::log(std::uniform_real_distribution<double>(0.0, 1.0)(rng)) < log_accept) {
          x.row(w) = y.transpose();
          lp[w] = lq;
          took[i] = 1;
        }
      });
      for (char t : took) accepted += t;
      moves += half;
    }
    if (step >= burn) {
      const Eigen::Index row = static_cast<Eigen::Index>(step - burn) * walkers;
      r.chain.middleRows(row, walkers) = x;
      r.log_posterior.segment(row, walkers) = lp;
    }
  }
  r.evaluations = static_cast<int>(walkers + moves);
  r.acceptance = static_cast<double>(accepted) / static_cast<double>(moves);
  for (Eigen::Index d = 0; d < dim; ++d) {
    Eigen::VectorXd mean(r.kept_steps);
    for (int s = 0; s < r.kept_steps; ++s)
      mean[s] = r.chain.col(d).segment(static_cast<Eigen::Index>(s) * walkers, walkers).mean();
    r.autocorrelation_steps.push_back(integrated_autocorrelation_time(mean));
  }
  const double worst = *std::max_element(r.autocorrelation_steps.begin(), r.autocorrelation_steps.end());
  if (r.acceptance < 0.1 || worst > 0.1 * r.kept_steps)
    r.warning = fmt::format(
        "the sampler did not mix: acceptance {:.3f} (below 0.1 is too low), largest autocorrelation time {:.1f} steps "
        "of {} kept (above a tenth is too long); its band is not to be trusted: raise steps or walkers",
        r.acceptance, worst, r.kept_steps);
  return r;
}

}  // namespace bb
