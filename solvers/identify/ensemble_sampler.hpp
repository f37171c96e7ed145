// An affine-invariant ensemble sampler (Goodman & Weare 2010, the stretch move; the parallel
// red-black form of Foreman-Mackey et al. 2013): walkers that move along the lines to one another,
// so a posterior stretched along a correlated direction (a joint's stiffness against the linear
// frequency) is sampled as easily as a round one. Its chain is the parameters' uncertainty beyond
// the linearised covariance, where the cost is not quadratic. Reproducible: the same seed gives
// the same chain whatever the thread count (each walker draws from its own stream).
#pragma once
#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace bb {

struct SamplerOptions {
  int steps = 1000;     // moves of every walker
  int burn_in = -1;     // steps dropped before the kept chain; -1: half of steps
  unsigned seed = 1;
  double stretch = 2.0;  // the stretch move's a
  int threads = 0;       // 0: one per core
};

struct SamplerResult {
  Eigen::MatrixXd chain;         // kept samples, (steps - burn_in) * walkers rows, step-major
  Eigen::VectorXd log_posterior; // of each kept sample
  double acceptance = 0.0;       // over all moves
  // Integrated autocorrelation time per parameter in steps (Sokal's window, c = 5, on the walkers'
  // mean), and the chain's kept steps: fewer than 10 of them per time and the band is not trusted.
  std::vector<double> autocorrelation_steps;
  int kept_steps = 0;
  int evaluations = 0;
  std::string warning;  // not mixed: acceptance below 0.1 or an autocorrelation time above a tenth of the chain
};

// `log_posterior` returns -inf outside the support (a step is then refused); `start` is walkers x
// parameters, every row inside the support. Throws std::invalid_argument for fewer than 2 x
// parameters walkers (and an odd count: the two halves move in turn), or a start outside.
SamplerResult sample_ensemble(const std::function<double(const Eigen::VectorXd&)>& log_posterior,
                              const Eigen::MatrixXd& start, const SamplerOptions& options);

// Sokal's integrated autocorrelation time of a series, in samples (1 for white noise).
double integrated_autocorrelation_time(const Eigen::VectorXd& series);

}  // namespace bb
