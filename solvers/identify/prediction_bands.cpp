#include "identify/prediction_bands.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bb {

Eigen::MatrixXd parameter_covariance(const CalibrationOutcome& o) {
  const auto n = static_cast<Eigen::Index>(o.std_devs.size());
  if (n == 0 || o.correlation.rows() != n) return {};
  Eigen::MatrixXd c(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      c(i, j) = o.correlation(i, j) * o.std_devs[static_cast<size_t>(i)] * o.std_devs[static_cast<size_t>(j)];
      if (!std::isfinite(c(i, j))) return {};
    }
  return c;
}

void set_linearised_bands(std::vector<FitPoint>& points, const std::vector<double>& values,
                          const Eigen::MatrixXd& covariance) {
  const auto n = static_cast<Eigen::Index>(values.size());
  if (covariance.rows() != n) return;
  for (FitPoint& p : points) {
    if (p.gradient.size() != values.size()) continue;
    Eigen::VectorXd g(n);
    for (Eigen::Index j = 0; j < n; ++j)
      g[j] = p.gradient[static_cast<size_t>(j)] * p.sigma / values[static_cast<size_t>(j)];
    if (!g.allFinite()) continue;
    p.band = std::sqrt(std::max(0.0, g.dot(covariance * g)));
  }
}

double normal_quantile(double level) {
  if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("a band level lies in (0, 1)");
  // Bisection on erf: the quantile z with P(|Z| <= z) = level.
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erf(mid / std::sqrt(2.0)) < level ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

BandCoverage band_coverage(const std::vector<FitPoint>& points, bool held_out, double level) {
  const double z = normal_quantile(level);
  BandCoverage c;
  for (const FitPoint& p : points) {
    if (p.held_out != held_out || !std::isfinite(p.band)) continue;
    ++c.points;
    if (std::abs(p.misfit()) <= z * std::hypot(p.band, p.sigma)) ++c.covered;
  }
  return c;
}

ResultTables with_band_columns(const ResultTables& at, const std::vector<ResultTables>& minus,
                               const std::vector<ResultTables>& plus, const std::vector<double>& step,
                               const Eigen::MatrixXd& covariance) {
  const auto k = static_cast<Eigen::Index>(step.size());
  ResultTables out = at;
  if (covariance.rows() != k || minus.size() != step.size() || plus.size() != step.size()) return out;
  for (auto& entry : out) {
    const std::string& name = entry.first;  // clang 14 cannot capture a structured binding (P1091)
    ResultTable& table = entry.second;
    const auto same_shape = [&](const ResultTables& run) {
      const auto t = run.find(name);
      return t != run.end() && t->second.columns == table.columns && t->second.values.rows() == table.values.rows();
    };
    if (!std::all_of(minus.begin(), minus.end(), same_shape) || !std::all_of(plus.begin(), plus.end(), same_shape))
      continue;
    const Eigen::Index rows = table.values.rows(), columns = table.values.cols();
    std::vector<std::string> names = table.columns;
    std::vector<Eigen::VectorXd> bands;
    for (Eigen::Index c = 1; c < columns; ++c) {  // column 0 is the key
      const std::string& column = table.columns[static_cast<size_t>(c)];
      if (column.ends_with("seconds") || column.ends_with("_per_step")) continue;  // wall time, not a prediction
      Eigen::MatrixXd d(rows, k);
      for (Eigen::Index j = 0; j < k; ++j)
        d.col(j) = (plus[static_cast<size_t>(j)].at(name).values.col(c) -
                    minus[static_cast<size_t>(j)].at(name).values.col(c)) /
                   (2.0 * step[static_cast<size_t>(j)]);
      bool moved = false;
      Eigen::VectorXd band(rows);
      for (Eigen::Index r = 0; r < rows; ++r) {
        const Eigen::VectorXd g = d.row(r).transpose();
        band[r] = g.allFinite() ? std::sqrt(std::max(0.0, g.dot(covariance * g))) : NAN;
        moved = moved || (std::isfinite(band[r]) && band[r] > 0.0);
      }
      if (!moved) continue;
      names.push_back(column + "_band_1sigma");
      bands.push_back(band);
    }
    if (bands.empty()) continue;
    Eigen::MatrixXd values(rows, columns + static_cast<Eigen::Index>(bands.size()));
    values.leftCols(columns) = table.values;
    for (size_t b = 0; b < bands.size(); ++b) values.col(columns + static_cast<Eigen::Index>(b)) = bands[b];
    table.columns = std::move(names);
    table.values = std::move(values);
  }
  return out;
}

}  // namespace bb
