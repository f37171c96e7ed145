#include "identify/synthetic_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <numeric>
#include <random>
#include <sstream>

#include "common/errors.hpp"
#include "common/input_number.hpp"

namespace bb {

namespace {

using Eigen::Index;

// The time derivative that turns a computed displacement (or compliance) into what a transducer of
// `unit` measures: 1 velocity (mobility), 2 acceleration (accelerance), 0 none.
int time_derivative(Dimension computed, Dimension unit) {
  if (computed == Dimension::length) return unit == Dimension::velocity ? 1 : unit == Dimension::acceleration ? 2 : 0;
  if (computed == Dimension::compliance)
    return unit == Dimension::mobility ? 1 : unit == Dimension::accelerance ? 2 : 0;
  return 0;
}

// w = 2 pi f of each kept row, from the table's frequency_hz column.
Eigen::ArrayXd harmonic_w(const ResultTable& table, const std::vector<Index>& rows) {
  const auto col = table.column_index("frequency_hz");
  if (!col)
    throw InputError(
        fmt::format("synthetic data: a velocity or acceleration needs the frequency of each row, but table "
                    "'{}' has no column 'frequency_hz'",
                    table.name));
  Eigen::ArrayXd w(static_cast<Index>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i)
    w[static_cast<Index>(i)] = 2.0 * std::numbers::pi * table.values(rows[i], *col);
  return w;
}

}  // namespace

void write_synthetic_data(const ResultTable& table, const SyntheticOptions& o, const std::filesystem::path& file) {
  int derivative = 0;  // of the written amplitude (1 velocity, 2 acceleration)
  if (o.every < 1) throw InputError("synthetic data: 'every' must be >= 1");
  std::vector<Index> rows;
  for (Index r = 0; r < table.values.rows(); r += o.every) rows.push_back(r);
  const auto n = static_cast<Index>(rows.size());
  std::vector<Eigen::VectorXd> values;  // per column, in the written unit
  std::vector<Unit> units;
  for (const SyntheticColumn& c : o.columns) {
    const auto col = table.column_index(c.result);
    if (!col) throw InputError(fmt::format("synthetic data: table '{}' has no column '{}'", table.name, c.result));
    const std::optional<Unit> unit = parse_unit(c.unit);
    if (!unit) throw InputError(fmt::format("synthetic data: unknown unit '{}' for column '{}'", c.unit, c.data));
    const std::optional<Dimension> dim = column_dimension(c.result);
    const int k = c.data == "amplitude" && dim ? time_derivative(*dim, unit->dimension) : 0;
    if (dim && *dim != unit->dimension && k == 0)
      throw InputError(fmt::format("synthetic data: '{}' is a {} but unit '{}' is a {}", c.result, dimension_name(*dim),
                                   c.unit, dimension_name(unit->dimension)));
    Eigen::VectorXd v(n);
    for (Index i = 0; i < n; ++i)
      v[i] = table.values(rows[static_cast<size_t>(i)], *col) * column_to_si(c.result) / unit->to_si;
    if (k > 0) derivative = k, v = (v.array() * harmonic_w(table, rows).pow(k)).matrix();
    values.push_back(v);
    units.push_back(*unit);
  }
  // A velocity or acceleration leads the displacement by 90 or 180 degrees (v = i w x, a = -w^2 x).
  for (size_t c = 0; c < o.columns.size(); ++c)
    if (o.columns[c].data == "phase" && derivative > 0)
      for (double& phase : values[c]) {
        const double turn = 2.0 * std::numbers::pi / units[c].to_si;
        phase = std::remainder(phase + derivative * 0.25 * turn, turn);
        if (phase <= -0.5 * turn) phase += turn;
      }
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Index> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  const std::vector<Index> outliers(order.begin(), order.begin() + std::min<Index>(o.outliers, n));
  std::vector<std::string> header;
  std::vector<Eigen::VectorXd> sigma_columns;
  std::vector<std::string> sigma_header;
  for (size_t k = 0; k < o.columns.size(); ++k) {
    const std::string& name = o.columns[k].data;
    Eigen::VectorXd& v = values[k];
    header.push_back(fmt::format("{} [{}]", name, o.columns[k].unit));
    Eigen::VectorXd sigma(n);
    if (name == "amplitude") {
      for (Index i = 0; i < n; ++i) sigma[i] = o.noise * std::abs(v[i]);
    } else if (name == "tangential_force") {
      sigma.setConstant(o.noise * v.cwiseAbs().maxCoeff());
    } else if (name == "frequency" && o.kind == DataKind::peaks) {
      for (Index i = 0; i < n; ++i) sigma[i] = o.frequency_noise * v[i];
    } else if (name == "force" && o.kind == DataKind::frf) {
      for (Index i = 0; i < n; ++i) sigma[i] = o.force_noise * std::abs(v[i]);
    } else if (name == "phase") {
      sigma.setConstant(o.phase_noise / units[k].to_si);
    } else {
      continue;  // abscissae (frequency of an FRF, force level, displacement) are exact
    }
    if (!(sigma.minCoeff() > 0.0)) continue;  // no noise asked for this column: no sigma column
    for (Index i = 0; i < n; ++i) v[i] += sigma[i] * gauss(rng);
    if (name == "amplitude" || name == "tangential_force")
      for (Index i : outliers) v[i] *= o.outlier_factor;
    // An absurd noise (1e308) writes what the data reader refuses: refuse it here, naming the column.
    for (Index i = 0; i < n; ++i)
      for (const double x : {v[i], sigma[i]})
        if (const std::string problem = number_problem(x); !problem.empty())
          throw InputError(fmt::format("synthetic data: column '{}', row {}: the noise made {:g}: {}; lower the noise",
                                       name, i + 1, x, problem));
    sigma_columns.push_back(sigma);
    // The loop's sigma column is force_sigma (measured_data.hpp).
    sigma_header.push_back(
        fmt::format("{}_sigma [{}]", name == "tangential_force" ? "force" : name, o.columns[k].unit));
  }
  std::ofstream out(file);
  if (!out) throw InputError(fmt::format("{}: cannot write", file.string()));
  std::istringstream lines(o.provenance);
  for (std::string line; std::getline(lines, line);) out << "# " << line << '\n';
  out << fmt::format(
      "# synthetic {} data from table '{}': Gaussian noise {:g} (relative), seed {}, {} outlier(s) x {:g}\n",
      data_kind_name(o.kind), table.name, o.noise, o.seed, outliers.size(), o.outlier_factor);
  header.insert(header.end(), sigma_header.begin(), sigma_header.end());
  for (size_t k = 0; k < header.size(); ++k) out << (k ? "," : "") << header[k];
  out << '\n';
  for (Index i = 0; i < n; ++i) {
    for (size_t k = 0; k < values.size(); ++k) out << (k ? "," : "") << fmt::format("{:.10g}", values[k][i]);
    for (const Eigen::VectorXd& s : sigma_columns) out << fmt::format(",{:.6g}", s[i]);
    out << '\n';
  }
  if (!out) throw InputError(fmt::format("{}: write failed", file.string()));
}

}  // namespace bb
