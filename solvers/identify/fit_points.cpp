#include "identify/fit_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "common/constants.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

using Eigen::Index;

double wrap_angle(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

const ResultTable& table_of(const CalibrationData& d, const ResultTables& tables) {
  const auto it = tables.find(d.table);
  if (it == tables.end())
    throw InputError(
        fmt::format("{}: calibration data '{}': the case computes no table '{}'", d.at.where(), d.name, d.table));
  return it->second;
}

// A result column in SI (a _deg column is turned into radians).
Eigen::VectorXd result_column(const CalibrationData& d, const ResultTable& t, const std::string& data_column) {
  const std::string& name = d.columns.at(data_column);
  const auto c = t.column_index(name);
  if (!c)
    throw InputError(
        fmt::format("{}: calibration data '{}': table '{}' has no column '{}'", d.at.where(), d.name, d.table, name));
  return t.values.col(*c) * column_to_si(name);
}

}  // namespace

void require_data_columns(const CalibrationData& d, const ResultTables& tables) {
  const ResultTable& t = table_of(d, tables);
  for (const auto& [data_column, result] : d.columns) result_column(d, t, data_column);
}

namespace {

double sigma_of(const MeasuredData& m, const std::string& column, Index row, double fallback) {
  return m.has(column + "_sigma") ? m.column(column + "_sigma")[row] : fallback;
}

// factor d(column)/d log p at one row, one entry per parameter; empty unless every column exists.
std::vector<double> row_dlog(const ResultTable& t, Index row, const std::string& column,
                             const std::vector<std::string>& parameters, double factor) {
  std::vector<double> out;
  for (const std::string& p : parameters) {
    const auto c = t.column_index(column + "_dlog_" + p);
    if (!c) return {};
    out.push_back(t.values(row, *c) * factor);
  }
  return out;
}

std::vector<FitPoint> peak_points(const CalibrationData& d, const ResultTable& t,
                                  const std::vector<std::string>& parameters) {
  const MeasuredData& m = d.data;
  const Eigen::VectorXd force = result_column(d, t, "force");
  std::map<std::string, Eigen::VectorXd> computed;  // the fitted columns, read once
  for (const char* q : {"frequency", "amplitude"})
    if (d.columns.count(q)) computed[q] = result_column(d, t, q);
  std::vector<FitPoint> points;
  for (Index i = 0; i < m.rows(); ++i) {
    const double f = m.column("force")[i];
    Index row = -1;
    for (Index r = 0; r < force.size(); ++r)
      if (std::abs(force[r] - f) <= 1e-9 * std::abs(f)) row = r;
    if (row < 0)
      throw InputError(fmt::format("{}: force level {:g} N has no row in table '{}' (case {})", m.where(i), f, d.table,
                                   d.at.where()));
    for (const char* q : {"frequency", "amplitude"}) {
      if (!d.columns.count(q)) continue;
      const bool is_frequency = std::string(q) == "frequency";
      const double measured = m.column(q)[i];
      const double sigma =
          sigma_of(m, q, i, (is_frequency ? d.frequency_uncertainty : d.amplitude_uncertainty) * measured);
      points.push_back({d.name, fmt::format("{} at {:g} N", q, f), q, f, measured, computed.at(q)[row], sigma, false,
                        row_dlog(t, row, d.columns.at(q), parameters, column_to_si(d.columns.at(q)) / sigma)});
    }
  }
  return points;
}

// Linear interpolation of y(x) at xq, x strictly increasing and xq within [x0, xn].
double interpolate(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double xq) {
  const auto* hi = std::upper_bound(x.data(), x.data() + x.size(), xq);
  const Index j = std::clamp<Index>(hi - x.data(), 1, x.size() - 1);
  const double s = (xq - x[j - 1]) / (x[j] - x[j - 1]);
  const double v = y[j - 1] + s * (y[j] - y[j - 1]);
  // On a row, its value: a neighbour without a solution (NaN) does not spoil it.
  if (std::isnan(v) && (s == 0.0 || s == 1.0)) return s == 0.0 ? y[j - 1] : y[j];
  return v;
}

// The log-sensitivity columns of result column `q` in SI, one per parameter; empty unless all exist.
std::vector<Eigen::VectorXd> dlog_columns(const CalibrationData& d, const ResultTable& t, const std::string& q,
                                          const std::vector<std::string>& parameters) {
  const std::string& name = d.columns.at(q);
  std::vector<Eigen::VectorXd> out;
  for (const std::string& p : parameters) {
    const auto c = t.column_index(name + "_dlog_" + p);
    if (!c) return {};
    out.push_back(t.values.col(*c) * column_to_si(name));
  }
  return out;
}

// Rows of the table in increasing frequency: as written (a level's sweep, a stepped sine up) or
// reversed (a stepped sine down). Throws when the frequencies go neither way.
std::vector<Index> increasing_rows(const CalibrationData& d, const Eigen::VectorXd& f) {
  std::vector<Index> rows(static_cast<size_t>(f.size()));
  for (Index r = 0; r < f.size(); ++r) rows[static_cast<size_t>(r)] = r;
  if (f.size() > 1 && f[1] < f[0]) std::reverse(rows.begin(), rows.end());
  for (size_t k = 1; k < rows.size(); ++k)
    if (!(f[rows[k]] > f[rows[k - 1]]))
      throw InputError(fmt::format(
          "{}: calibration data '{}': the frequencies of table '{}' neither increase nor decrease (row {}); use a grid "
          "sweep or a stepped sine",
          d.at.where(), d.name, d.table, std::max(rows[k], rows[k - 1]) + 1));
  return rows;
}

// Data measured at a force per point against a stepped sine: every table row at a data frequency
// must have been solved at that row's force (else the case's stepped sine read another file).
void require_same_forces(const CalibrationData& d, const ResultTable& t, const Eigen::VectorXd& f) {
  const MeasuredData& m = d.data;
  const Eigen::VectorXd force = result_column(d, t, "force");
  Index matched = 0;
  for (Index i = 0; i < m.rows(); ++i) {
    const double fq = m.column("frequency")[i], fm = m.column("force")[i];
    for (Index r = 0; r < f.size(); ++r) {
      if (std::abs(f[r] - fq) > 1e-9 * fq) continue;
      if (std::abs(force[r] - fm) > 1e-9 * fm)
        throw InputError(
            fmt::format("{}: measured at {:g} N, but table '{}' solved {:g} Hz at {:g} N (case {}): the "
                        "stepped sine must read this file",
                        m.where(i), fm, d.table, fq, force[r], d.at.where()));
      ++matched;
    }
  }
  if (matched == 0)
    throw InputError(
        fmt::format("{}: calibration data '{}' give the force of each point, but no row of table '{}' lies "
                    "at their frequencies: map the table of the stepped sine that reads {}",
                    d.at.where(), d.name, d.table, m.file.string()));
}

// Data of a response-controlled curve against a table that holds another level (a 20 m/s^2
// curve mapped onto the 5 m/s^2 table): the medians of the measured and the held amplitude, in
// the quantity the file holds, more than 10 % apart. `f` and `held` in increasing frequency.
void require_held_level(const CalibrationData& d, const Eigen::VectorXd& f, const Eigen::VectorXd& held) {
  const MeasuredData& m = d.data;
  std::vector<double> measured, computed;
  for (Index i = 0; i < m.rows(); ++i) {
    const double fq = m.column("frequency")[i];
    if (f.size() < 2 || fq < f[0] || fq > f[f.size() - 1]) continue;  // the range is checked per point
    const double h = interpolate(f, held, fq), w = std::pow(kTwoPi * fq, m.derivative);
    if (!std::isfinite(h)) continue;  // a point without a solution
    measured.push_back(m.column("amplitude")[i] * w);
    computed.push_back(h * w);
  }
  if (measured.empty()) return;
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double a = median(measured), b = median(computed);
  const char* const unit[] = {"m", "m/s", "m/s^2"};
  if (std::abs(a / b - 1.0) > 0.1)
    throw InputError(fmt::format(
        "{}: calibration data '{}': {} was held at {:.4g} {} (the median of its amplitude column) but table '{}' "
        "holds {:.4g} {}: map the table of the response control at the data's level",
        d.at.where(), d.name, m.file.string(), a, unit[m.derivative], d.table, b, unit[m.derivative]));
}

std::vector<FitPoint> frf_points(const CalibrationData& d, const ResultTable& t,
                                 const std::vector<std::string>& parameters) {
  const MeasuredData& m = d.data;
  const Eigen::VectorXd written = result_column(d, t, "frequency");
  const std::vector<Index> order = increasing_rows(d, written);
  // A response-controlled curve measured the force that held the amplitude; a force-controlled
  // one was driven by its force.
  const bool force_measured = m.has("force") && t.column_index("held_m").has_value();
  if (m.has("force") && !force_measured) require_same_forces(d, t, written);
  const std::vector<const char*> quantities =
      force_measured ? std::vector<const char*>{"force", "phase"} : std::vector<const char*>{"amplitude", "phase"};
  const auto sorted = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd out(v.size());
    for (size_t k = 0; k < order.size(); ++k) out[static_cast<Index>(k)] = v[order[k]];
    return out;
  };
  const Eigen::VectorXd f = sorted(written);
  if (force_measured && m.has("amplitude")) require_held_level(d, f, sorted(t.values.col(*t.column_index("held_m"))));
  // The fitted columns and their sensitivities, read once for all rows.
  struct Fitted {
    Eigen::VectorXd y;
    std::vector<Eigen::VectorXd> dlog;
  };
  std::map<std::string, Fitted> fitted;
  for (const char* q : quantities) {
    if (!d.columns.count(q)) continue;
    Fitted& c = fitted[q];
    c.y = sorted(result_column(d, t, q));
    if (std::string(q) == "phase")  // unwrap so the interpolation does not cross a 2 pi jump
      for (Index r = 1; r < c.y.size(); ++r) c.y[r] = c.y[r - 1] + wrap_angle(c.y[r] - c.y[r - 1]);
    for (const Eigen::VectorXd& dy : dlog_columns(d, t, q, parameters)) c.dlog.push_back(sorted(dy));
  }
  std::vector<FitPoint> points;
  for (Index i = 0; i < m.rows(); ++i) {
    const double fq = m.column("frequency")[i];
    const double slack = f.size() ? 1e-9 * std::abs(f[f.size() - 1]) : 0.0;  // the grid's ends carry rounding
    if (f.size() < 2 || fq < f[0] - slack || fq > f[f.size() - 1] + slack)
      throw InputError(
          fmt::format("{}: frequency {:g} Hz lies outside the computed range [{:g}, {:g}] Hz of table '{}' (case {})",
                      m.where(i), fq, f.size() ? f[0] : NAN, f.size() ? f[f.size() - 1] : NAN, d.table, d.at.where()));
    for (const char* q : quantities) {
      if (!d.columns.count(q)) continue;
      const bool phase = std::string(q) == "phase";
      const double measured = m.column(q)[i];
      const Fitted& c = fitted.at(q);
      const double relative = std::string(q) == "force" ? d.force_uncertainty : d.amplitude_uncertainty;
      const double sigma = sigma_of(m, q, i, phase ? d.phase_uncertainty : relative * measured);
      const double at = std::clamp(fq, f[0], f[f.size() - 1]);
      // Linear in the table's values, so the interpolated derivative is the derivative of the
      // interpolation (the unwrapping adds constants only).
      std::vector<double> gradient;
      for (const Eigen::VectorXd& dy : c.dlog) gradient.push_back(interpolate(f, dy, at) / sigma);
      points.push_back({d.name, fmt::format("{} at {:.6g} Hz", q, fq), q, fq, measured, interpolate(f, c.y, at), sigma,
                        phase, std::move(gradient)});
    }
  }
  return points;
}

// One monotonic run of the computed loop, stored with increasing displacement.
struct Branch {
  Eigen::VectorXd u, force;
  int direction = 0;  // +1 loading (u increasing in time), -1 unloading
};

std::vector<Branch> branches_of(const Eigen::VectorXd& u, const Eigen::VectorXd& force) {
  std::vector<Branch> out;
  Index begin = 0;
  const auto close = [&](Index end) {
    if (end - begin < 1) return;
    const int dir = u[end] > u[begin] ? 1 : -1;
    std::vector<std::pair<double, double>> pts;
    for (Index k = begin; k <= end; ++k) pts.emplace_back(u[k], force[k]);
    if (dir < 0) std::reverse(pts.begin(), pts.end());
    Branch b;
    b.direction = dir;
    b.u.resize(static_cast<Index>(pts.size()));
    b.force.resize(static_cast<Index>(pts.size()));
    for (size_t k = 0; k < pts.size(); ++k)
      b.u[static_cast<Index>(k)] = pts[k].first, b.force[static_cast<Index>(k)] = pts[k].second;
    out.push_back(std::move(b));
    begin = end;
  };
  for (Index k = 1; k + 1 < u.size(); ++k)
    if ((u[k] - u[k - 1]) * (u[k + 1] - u[k]) < 0) close(k);
  close(u.size() - 1);
  return out;
}

std::vector<FitPoint> hysteresis_points(const CalibrationData& d, const ResultTable& t) {
  const MeasuredData& m = d.data;
  const Eigen::VectorXd u = result_column(d, t, "relative_displacement");
  const Eigen::VectorXd force = result_column(d, t, "tangential_force");
  std::vector<Branch> branches = branches_of(u, force);
  // Strictly increasing displacement inside each branch (a stuck or open stretch may repeat a value).
  for (Branch& b : branches)
    for (Index k = 1; k < b.u.size(); ++k) b.u[k] = std::max(b.u[k], std::nextafter(b.u[k - 1], INFINITY));
  const Eigen::VectorXd& um = m.column("relative_displacement");
  const Eigen::VectorXd& tm = m.column("tangential_force");
  const double scale = tm.cwiseAbs().maxCoeff();
  std::vector<FitPoint> points;
  const Index n = m.rows();
  for (Index i = 0; i < n; ++i) {
    const double du = um[(i + 1) % n] - um[(i + n - 1) % n];  // the loop is periodic
    const int dir = du >= 0 ? 1 : -1;
    double computed = NAN, best_gap = INFINITY;
    for (const Branch& b : branches) {
      if (b.direction != dir || b.u.size() < 2) continue;
      const double lo = b.u[0], hi = b.u[b.u.size() - 1];
      const double gap = um[i] < lo ? lo - um[i] : um[i] > hi ? um[i] - hi : 0.0;
      if (gap < best_gap) best_gap = gap, computed = interpolate(b.u, b.force, std::clamp(um[i], lo, hi));
    }
    if (!std::isfinite(computed))
      throw InputError(fmt::format("{}: table '{}' has no loop branch moving {} to compare with (case {})", m.where(i),
                                   d.table, dir > 0 ? "forward" : "backward", d.at.where()));
    const double sigma = sigma_of(m, "force", i, d.force_uncertainty * scale);
    points.push_back({d.name,
                      fmt::format("force at {:.4g} m ({})", um[i], dir > 0 ? "loading" : "unloading"),
                      "tangential_force",
                      um[i],
                      tm[i],
                      computed,
                      sigma,
                      false,
                      {}});
  }
  return points;
}

}  // namespace

double FitPoint::misfit() const { return angle ? wrap_angle(computed - measured) : computed - measured; }

double FitPoint::display_scale() const { return angle ? 180.0 / std::numbers::pi : 1.0; }

namespace {

// The unit a result column's values are shown in, by its name's suffix (column_dimension).
std::string shown_unit(const std::string& column) {
  const std::optional<Dimension> d = column_dimension(column);
  if (!d) return "";
  switch (*d) {
    case Dimension::length:
      return "m";
    case Dimension::force:
      return "N";
    case Dimension::frequency:
      return "Hz";
    case Dimension::angle:
      return "deg";
    case Dimension::compliance:
      return "m/N";
    case Dimension::stiffness:
      return "N/m";
    case Dimension::time:
      return "s";
    default:
      return "";
  }
}

}  // namespace

std::vector<FitPoint> check_points(const std::vector<CheckEntry>& entries, const CalibrationSpec& cal,
                                   const ResultTable* table, const std::vector<std::string>& parameters) {
  std::vector<FitPoint> points;
  for (const CheckEntry& e : entries) {
    const double sigma = uncertainty_of(cal, e.group) * std::abs(e.reference);
    std::vector<double> gradient;
    if (table && !parameters.empty())
      for (Index r = 0; r < table->values.rows(); ++r)
        if (std::lround(table->values(r, 0)) == e.computed_key)
          gradient = row_dlog(*table, r, e.column, parameters, 1.0 / sigma);
    points.push_back({e.group, e.name.substr(std::min(e.name.size(), e.group.size() + 2)), "check",
                      static_cast<double>(e.key), e.reference, e.computed, sigma, false, std::move(gradient)});
    points.back().unit = shown_unit(e.column);
  }
  return points;
}

std::vector<FitPoint> data_points(const CalibrationData& d, const ResultTables& tables,
                                  const std::vector<std::string>& parameters) {
  const ResultTable& t = table_of(d, tables);
  std::vector<FitPoint> points = d.data.kind == DataKind::peaks ? peak_points(d, t, parameters)
                                 : d.data.kind == DataKind::frf ? frf_points(d, t, parameters)
                                                                : hysteresis_points(d, t);
  for (FitPoint& p : points) {
    p.held_out = d.held_out;
    if (const auto c = d.columns.find(p.quantity); c != d.columns.end()) p.unit = shown_unit(c->second);
  }
  return points;
}

void require_solved_points(const std::vector<FitPoint>& points, const CalibrationSpec& cal,
                           const ResultTables& tables) {
  for (const FitPoint& p : points) {
    if (p.held_out || std::isfinite(p.computed)) continue;
    for (const CalibrationData& d : cal.data) {
      const auto t = d.name == p.set && d.data.kind == DataKind::frf ? tables.find(d.table) : tables.end();
      if (t == tables.end()) continue;
      const ResultTable& table = t->second;
      const auto failure = std::find(table.text_columns.begin(), table.text_columns.end(), "failure");
      const auto hz = table.column_index("frequency_hz");
      if (failure == table.text_columns.end() || !hz) continue;
      const std::vector<std::string>& why = table.text[static_cast<size_t>(failure - table.text_columns.begin())];
      Index nearest = -1;  // the failed row next to the point
      for (Index r = 0; r < table.values.rows(); ++r)
        if (!why[static_cast<size_t>(r)].empty() &&
            (nearest < 0 || std::abs(table.values(r, *hz) - p.x) < std::abs(table.values(nearest, *hz) - p.x)))
          nearest = r;
      if (nearest < 0) continue;
      throw SolverError(fmt::format(
          "{}: calibration data '{}': at the start values the model has no solution at {:.6g} Hz of table '{}', "
          "next to the measured {} ({}); a fit cannot start there: change the start (calibrate --set) or the "
          "solver's settings",
          d.at.where(), d.name, table.values(nearest, *hz), d.table, p.label, why[static_cast<size_t>(nearest)]));
    }
  }
}

}  // namespace bb
