// Prediction bands: the linearised band of a fitted model covers held-out measurements as often as
// its level says (20 seeds of synthetic data with known noise), and the ensemble sampler recovers a
// correlated Gaussian's mean and covariance, repeats itself whatever the threads, and says when it
// has not mixed.
#include "identify/prediction_bands.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "identify/ensemble_sampler.hpp"
#include "identify/least_squares_fit.hpp"

namespace bb {
namespace {

// y(t) = A exp(-t / tau) measured with 2 % Gaussian noise: 12 fitted points on [0, 2], 9 held out
// between them; gradients d r / d log p exact.
struct Decay {
  std::vector<double> fitted_t, held_t, fitted_y, held_y;
  static double y(const std::vector<double>& p, double t) { return p[0] * std::exp(-t / p[1]); }
  static std::vector<double> dlog(const std::vector<double>& p, double t) {
    return {y(p, t), y(p, t) * t / p[1]};  // p dy/dp for A and tau
  }
};

Decay synthetic(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.02);
  const std::vector<double> truth = {3.0, 0.7};
  Decay d;
  for (int k = 0; k < 12; ++k) d.fitted_t.push_back(2.0 * k / 11.0);
  for (int k = 0; k < 9; ++k) d.held_t.push_back(2.0 * (k + 0.5) / 9.0);
  for (double t : d.fitted_t) d.fitted_y.push_back(Decay::y(truth, t) * (1.0 + noise(rng)));
  for (double t : d.held_t) d.held_y.push_back(Decay::y(truth, t) * (1.0 + noise(rng)));
  return d;
}

std::vector<FitPoint> points(const Decay& d, const std::vector<double>& p, bool with_held_out) {
  std::vector<FitPoint> out;
  const auto add = [&](double t, double measured, bool held) {
    FitPoint q;
    q.set = held ? "held" : "fitted";
    q.x = t;
    q.measured = measured;
    q.computed = Decay::y(p, t);
    q.sigma = 0.02 * Decay::y(std::vector<double>{3.0, 0.7}, t);  // the known noise
    for (double g : Decay::dlog(p, t)) q.gradient.push_back(g / q.sigma);
    q.held_out = held;
    out.push_back(q);
  };
  for (size_t k = 0; k < d.fitted_t.size(); ++k) add(d.fitted_t[k], d.fitted_y[k], false);
  if (with_held_out)
    for (size_t k = 0; k < d.held_t.size(); ++k) add(d.held_t[k], d.held_y[k], true);
  return out;
}

TEST(PredictionBands, NinetyFivePercentBandsCoverHeldOutPointsAsOftenAsTheirLevelOverTwentySeeds) {
  BandCoverage total;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Decay d = synthetic(seed);
    CalibrationSpec spec;
    spec.parameters = {{"A", 0.1, 10.0, 1.0}, {"tau", 0.05, 5.0, 1.0}};
    spec.threads = 1;
    spec.max_iterations = 100;
    const CalibrationOutcome o = fit_parameters(
        spec, [&](const std::vector<double>& v, bool) { return points(d, v, false); }, true, 12);
    ASSERT_TRUE(o.converged) << o.termination;
    std::vector<FitPoint> all = points(d, o.values, true);
    set_linearised_bands(all, o.values, parameter_covariance(o));
    for (const FitPoint& p : all) ASSERT_TRUE(std::isfinite(p.band) && p.band > 0.0);
    const BandCoverage c = band_coverage(all, true);
    total.points += c.points, total.covered += c.covered;
  }
  EXPECT_EQ(total.points, 180);
  EXPECT_GE(total.share(), 0.90);
  EXPECT_LE(total.share(), 0.99);
}

// The band is the delta method's: for y = A (one parameter, linear) it is exactly A's deviation.
TEST(PredictionBands, ALinearModelsBandIsItsParametersDeviation) {
  FitPoint p;
  p.sigma = 0.1;
  p.computed = 2.0;
  p.gradient = {2.0 / 0.1};  // A dy/dA / sigma with y = A
  std::vector<FitPoint> pts = {p};
  Eigen::MatrixXd c(1, 1);
  c(0, 0) = 0.03 * 0.03;
  set_linearised_bands(pts, {2.0}, c);
  EXPECT_NEAR(pts[0].band, 0.03, 1e-15);
  EXPECT_NEAR(normal_quantile(0.95), 1.959963984540054, 1e-12);
  EXPECT_THROW(normal_quantile(1.0), std::invalid_argument);
}

double gaussian_log_density(const Eigen::VectorXd& x) {
  static const Eigen::Matrix2d inverse = [] {
    Eigen::Matrix2d c;
    c << 1.0, 0.95, 0.95, 1.0;  // strongly correlated, as a joint's stiffness and frequency
    return Eigen::Matrix2d(c.inverse());
  }();
  const Eigen::Vector2d d = x - Eigen::Vector2d(1.0, -2.0);
  return -0.5 * d.dot(inverse * d);
}

Eigen::MatrixXd ball(int walkers, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 0.1);
  Eigen::MatrixXd s(walkers, 2);
  for (int w = 0; w < walkers; ++w) s.row(w) << 1.0 + n(rng), -2.0 + n(rng);
  return s;
}

TEST(EnsembleSampler, RecoversACorrelatedGaussiansMeanAndCovariance) {
  SamplerOptions o;
  o.steps = 4000;
  o.seed = 3;
  o.threads = 1;
  const SamplerResult r = sample_ensemble(gaussian_log_density, ball(16, 1), o);
  const Eigen::RowVectorXd mean = r.chain.colwise().mean();
  const Eigen::MatrixXd centred = r.chain.rowwise() - mean;
  const Eigen::MatrixXd cov = centred.transpose() * centred / static_cast<double>(r.chain.rows() - 1);
  EXPECT_NEAR(mean[0], 1.0, 0.08);
  EXPECT_NEAR(mean[1], -2.0, 0.08);
  EXPECT_NEAR(cov(0, 0), 1.0, 0.1);
  EXPECT_NEAR(cov(1, 1), 1.0, 0.1);
  EXPECT_NEAR(cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 0.95, 0.02);
  EXPECT_GT(r.acceptance, 0.2);
  EXPECT_LT(r.acceptance, 0.9);
  EXPECT_TRUE(r.warning.empty()) << r.warning;
}

TEST(EnsembleSampler, TheSameSeedGivesTheSameChainWhateverTheThreads) {
  SamplerOptions o;
  o.steps = 200;
  o.threads = 1;
  const SamplerResult one = sample_ensemble(gaussian_log_density, ball(8, 2), o);
  o.threads = 4;
  const SamplerResult four = sample_ensemble(gaussian_log_density, ball(8, 2), o);
  EXPECT_EQ((one.chain - four.chain).cwiseAbs().maxCoeff(), 0.0);
}

TEST(EnsembleSampler, AShortChainSaysItHasNotMixed) {
  SamplerOptions o;
  o.steps = 12;
  o.threads = 1;
  const SamplerResult r = sample_ensemble(gaussian_log_density, ball(4, 5), o);
  EXPECT_NE(r.warning.find("did not mix"), std::string::npos);
}

TEST(EnsembleSampler, RefusesFewerWalkersThanTwiceTheParameters) {
  EXPECT_THROW(sample_ensemble(gaussian_log_density, ball(3, 1), {}), std::invalid_argument);
  EXPECT_THROW(sample_ensemble(gaussian_log_density, ball(5, 1), {}), std::invalid_argument);  // odd
}

// A cross-check's table with band columns: y = 3 p1 + p2^2 at p = (2, 5) has the gradient (3, 10);
// with C = [[0.04, 0.01], [0.01, 0.09]] its band is sqrt(g^T C g); the key column and a column
// no parameter moves get none, and a table some run lacks is left as it was.
TEST(PredictionBands, CrossCheckTablesGetABandBesideEveryColumnTheParametersMove) {
  const auto tables = [](double p1, double p2) {
    ResultTables t;
    t.emplace("peaks", table_from_rows("peaks", {"level", "fixed", "y"},
                                       {{1.0, 7.0, 3.0 * p1 + p2 * p2}, {2.0, 7.0, 2.0 * (3.0 * p1 + p2 * p2)}}));
    return t;
  };
  const std::vector<double> step = {1e-4, 1e-4};
  std::vector<ResultTables> minus = {tables(2.0 - 1e-4, 5.0), tables(2.0, 5.0 - 1e-4)};
  std::vector<ResultTables> plus = {tables(2.0 + 1e-4, 5.0), tables(2.0, 5.0 + 1e-4)};
  Eigen::Matrix2d c;
  c << 0.04, 0.01, 0.01, 0.09;
  ResultTables at = tables(2.0, 5.0);
  at.emplace("only_here", table_from_rows("only_here", {"k", "v"}, {{1.0, 2.0}}));
  const ResultTables out = with_band_columns(at, minus, plus, step, c);
  const ResultTable& peaks = out.at("peaks");
  ASSERT_EQ(peaks.columns, (std::vector<std::string>{"level", "fixed", "y", "y_band_1sigma"}));
  const Eigen::Vector2d g(3.0, 10.0);
  EXPECT_NEAR(peaks.values(0, 3), std::sqrt(g.dot(c * g)), 1e-6);
  EXPECT_NEAR(peaks.values(1, 3), 2.0 * std::sqrt(g.dot(c * g)), 1e-6);
  EXPECT_EQ(out.at("only_here").columns.size(), 2u);
}

}  // namespace
}  // namespace bb
