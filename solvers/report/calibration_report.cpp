#include "report/calibration_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

#include "identify/prediction_bands.hpp"
#include "report/gnuplot.hpp"
#include "report/html_page.hpp"
#include "report/plots.hpp"
#include "report/writers.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

std::ofstream open_out(const fs::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  return out;
}

// Root mean square of the residuals (misfit / sigma) of the points of one set, or of all fitted ones.
double rms_residual(const std::vector<FitPoint>& points, const std::string& set = {}) {
  double sum = 0.0;
  int n = 0;
  for (const FitPoint& p : points)
    if (set.empty() ? !p.held_out : p.set == set) sum += p.residual() * p.residual(), ++n;
  return n ? std::sqrt(sum / n) : 0.0;
}

// The largest |computed - measured| / |measured| of a set's points.
double largest_relative_misfit(const std::vector<FitPoint>& points, const std::string& set) {
  double worst = 0.0;
  for (const FitPoint& p : points)
    if (p.set == set && !p.angle && p.measured != 0.0) worst = std::max(worst, std::abs(p.misfit() / p.measured));
  return worst;
}

// The sets of the fitted points, or of the held-out ones.
std::vector<std::string> sets_of(const std::vector<FitPoint>& points, bool held_out = false) {
  std::vector<std::string> sets;
  for (const FitPoint& p : points)
    if (p.held_out == held_out && std::find(sets.begin(), sets.end(), p.set) == sets.end()) sets.push_back(p.set);
  return sets;
}

std::string slug(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

// The measured points of one quantity of a data set with their computed values at the start and
// at the identified values, and the computed curves (x column, y column of the fitted table).
Plot plot_data_set(const CalibrationOutcome& o, const CalibrationData& d, const std::string& quantity,
                   const fs::path& out_dir) {
  const std::string stem = "fit_" + slug(d.name) + "_" + quantity;
  const bool curve = d.data.kind != DataKind::peaks;
  const std::string x_col = d.data.kind == DataKind::frf          ? "frequency"
                            : d.data.kind == DataKind::hysteresis ? "relative_displacement"
                                                                  : "force";
  const std::string y_col = quantity == "tangential_force" ? "tangential_force" : quantity;
  const double y_scale = quantity == "phase" ? 180.0 / std::numbers::pi : 1.0;  // phases plotted in degrees
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# measured: x y sigma | computed at the start | computed at the identified values | 95 % prediction "
           "interval low high\n";
    const double z = normal_quantile(o.spec.band_level);
    for (size_t k = 0; k < o.after.size() && k < o.before.size(); ++k) {
      const FitPoint& a = o.after[k];
      if (a.set != d.name || a.quantity != quantity) continue;
      const double half = z * std::hypot(std::isfinite(a.band) ? a.band : a.sampled_band, a.sigma);
      out << a.x << ' ' << a.measured * y_scale << ' ' << a.sigma * y_scale << ' ' << o.before[k].computed * y_scale
          << ' ' << a.computed * y_scale << ' ' << (a.computed - half) * y_scale << ' ' << (a.computed + half) * y_scale
          << '\n';
    }
    for (const ResultTables* tables : {&o.curves_before, &o.curves_after}) {
      out << "\n\n";
      const auto t = tables->find(d.table);
      if (!curve || t == tables->end()) {
        out << "nan nan\n";
        continue;
      }
      const auto xi = t->second.column_index(d.columns.at(x_col));
      const auto yi = t->second.column_index(d.columns.at(y_col));
      const double y_si = column_to_si(d.columns.at(y_col)) * y_scale;
      for (Eigen::Index r = 0; xi && yi && r < t->second.values.rows(); ++r)
        out << t->second.values(r, *xi) * column_to_si(d.columns.at(x_col)) << ' ' << t->second.values(r, *yi) * y_si
            << '\n';
    }
  }
  const std::string x_label = d.data.kind == DataKind::frf          ? "frequency [Hz]"
                              : d.data.kind == DataKind::hysteresis ? "relative displacement [m]"
                                                                    : "force level [N]";
  const std::optional<Dimension> y_dim = column_dimension(d.columns.at(y_col));
  const std::string y_label = quantity == "phase"              ? "phase [deg]"
                              : quantity == "frequency"        ? "frequency [Hz]"
                              : quantity == "tangential_force" ? "tangential force [N]"
                              : quantity == "force"            ? "force [N]"
                              : y_dim == Dimension::compliance ? "amplitude per newton [m/N]"
                                                               : "amplitude [m]";
  std::string shown = quantity;
  std::replace(shown.begin(), shown.end(), '_', ' ');  // gnuplot would subscript after _
  const std::string title = fmt::format("{}: {} measured (points, 1 sigma) and computed", d.name, shown);
  std::string script = fmt::format(
      "set title '{}'\nset xlabel '{}'\nset ylabel '{}'\nset grid\nset key outside right\nset datafile missing 'nan'\n",
      gnuplot_quote(title), x_label, y_label);
  if (!curve) script += "set logscale x\n";  // force levels span decades
  if (curve) {
    script += fmt::format(
        "plot '{0}.dat' index 0 using 1:6:7 with filledcurves fs transparent solid 0.25 lc rgb '#d62728' "
        "title 'prediction interval', \\\n"
        "     '{0}.dat' index 0 using 1:2:3 with yerrorbars pt 7 ps 0.5 lc rgb 'black' title 'measured', \\\n"
        "     '{0}.dat' index 1 using 1:2 with lines dt 2 lc rgb '#1f77b4' title 'start values', \\\n"
        "     '{0}.dat' index 2 using 1:2 with lines lw 2 lc rgb '#d62728' title 'identified'\n",
        stem);
  } else {
    script += fmt::format(
        "plot '{0}.dat' index 0 using 1:2:3 with yerrorbars pt 7 ps 0.6 lc rgb 'black' title 'measured', \\\n"
        "     '{0}.dat' index 0 using 1:4 with points pt 6 lc rgb '#1f77b4' title 'start values', \\\n"
        "     '{0}.dat' index 0 using 1:5 with points pt 9 ps 1.2 lc rgb '#d62728' title 'identified'\n",
        stem);
  }
  return draw(out_dir, stem, title, script);
}

// The file names of a case (model, mesh, measured data, references, cross-check) made relative
// to `to` instead of the case's folder `from`, so that a copy written in `to` runs there.
void rebase_file_names(toml::node& node, const fs::path& from, const fs::path& to) {
  static constexpr std::array<std::string_view, 7> keys{"file",           "nodes",       "elements",  "reference",
                                                        "reference_case", "cross_check", "model_from"};
  if (toml::table* t = node.as_table()) {
    for (auto&& [key, value] : *t) {
      toml::value<std::string>* name = value.as_string();
      if (!name || std::find(keys.begin(), keys.end(), key.str()) == keys.end()) {
        rebase_file_names(value, from, to);
        continue;
      }
      const fs::path path(name->get());
      if (!path.is_relative()) continue;
      const fs::path target = fs::absolute(from / path).lexically_normal();
      std::error_code failed;
      const fs::path relative = fs::relative(target, fs::absolute(to), failed);
      name->get() = (failed || relative.empty() ? target : relative).generic_string();
    }
  } else if (toml::array* a = node.as_array()) {
    for (toml::node& element : *a) rebase_file_names(element, from, to);
  }
}

// The machine-readable outputs; calibrated.toml only for a converged fit.
void write_calibration_files(const CalibrationOutcome& o, const fs::path& case_file, const fs::path& out_dir) {
  if (!o.cross_check_tables.empty()) {
    fs::create_directories(out_dir / "cross_check");
    for (const auto& [name, table] : o.cross_check_tables)
      write_table_csv(table, out_dir / "cross_check" / (name + ".csv"));
  }
  {
    std::ofstream out = open_out(out_dir / "identification.csv");
    out << "parameter,start,value,std,lower,upper\n";
    for (size_t i = 0; i < o.values.size(); ++i) {
      const auto& p = o.spec.parameters[i];
      out << fmt::format("{},{:.10g},{:.10g},{:.6g},{:.10g},{:.10g}\n", p.path, p.start, o.values[i], o.std_devs[i],
                         p.lower, p.upper);
    }
  }
  {
    std::ofstream out = open_out(out_dir / "convergence.csv");
    out << "iteration,cost\n";
    for (const auto& [it, cost] : o.history) out << fmt::format("{},{:.10g}\n", it, cost);
  }
  // A failed fit must not leave an earlier calibrated.toml looking current; its values are written
  // as restart.toml instead, what `calibrate --restart-from` continues.
  fs::remove(out_dir / "calibrated.toml");
  fs::remove(out_dir / "restart.toml");
  {
    std::ofstream out = open_out(out_dir / (o.converged ? "calibrated.toml" : "restart.toml"));
    out << fmt::format(
        "# {} with the values {} by `bladebench calibrate` (comments are not kept; file names relative to "
        "this folder).\n",
        case_file.string(),
        o.converged ? "identified" : "where the fit stopped, NOT converged, to continue with --restart-from,");
    toml::table calibrated = o.calibrated;
    rebase_file_names(calibrated, case_file.parent_path(), out_dir);
    out << calibrated << '\n';
  }
  {
    std::ofstream out = open_out(out_dir / "starts.csv");
    out << "start,converged,initial_cost,final_cost,iterations";
    for (const auto& p : o.spec.parameters) out << ",start_" << p.path << ",value_" << p.path;
    out << '\n';
    for (size_t s = 0; s < o.starts.size(); ++s) {
      const CalibrationStart& r = o.starts[s];
      out << fmt::format("{},{},{:.10g},{:.10g},{}", s + 1, r.converged ? 1 : 0, r.initial_cost, r.final_cost,
                         r.iterations);
      for (size_t i = 0; i < r.values.size(); ++i) out << fmt::format(",{:.10g},{:.10g}", r.start[i], r.values[i]);
      out << '\n';
    }
  }
  {
    std::ofstream out = open_out(out_dir / "fitted_points.csv");
    // Values in the unit of the `unit` column (phases in degrees, as the data and tables give them).
    // band_1sigma: the identified values' uncertainty carried into the computed value (linearised);
    // band_lower/band_upper: the prediction interval of a measurement at [calibration] band_level,
    // computed +- z sqrt(band^2 + sigma^2); the sampled_ columns the same from posterior samples.
    out << "set,point,quantity,unit,x,measured,sigma,computed_start,residual_start,computed_identified,residual_"
           "identified,held_out,band_1sigma,band_lower,band_upper,sampled_band_1sigma,sampled_band_lower,sampled_band_"
           "upper\n";
    const double z = normal_quantile(o.spec.band_level);
    for (size_t k = 0; k < o.after.size() && k < o.before.size(); ++k) {
      const FitPoint& a = o.after[k];
      const double u = a.display_scale(), half = z * std::hypot(a.band, a.sigma),
                   sampled = z * std::hypot(a.sampled_band, a.sigma);
      out << fmt::format(
          "\"{}\",\"{}\",{},{},{:.10g},{:.10g},{:.6g},{:.10g},{:.6g},{:.10g},{:.6g},{},{:.6g},{:.10g},{:."
          "10g},{:.6g},{:.10g},{:.10g}\n",
          a.set, a.label, a.quantity, a.unit, a.x, a.measured * u, a.sigma * u, o.before[k].computed * u,
          o.before[k].residual(), a.computed * u, a.residual(), a.held_out ? 1 : 0, a.band * u, (a.computed - half) * u,
          (a.computed + half) * u, a.sampled_band * u, (a.computed - sampled) * u, (a.computed + sampled) * u);
    }
  }
}

// How often the prediction bands hold the measured points, linearised and sampled.
void write_band_summary(const CalibrationOutcome& o, std::ostream& md) {
  const double level = 100.0 * o.spec.band_level;
  const BandCoverage held = band_coverage(o.after, true, o.spec.band_level),
                     fitted = band_coverage(o.after, false, o.spec.band_level);
  md << (held.points + fitted.points == 0
             ? std::string("Prediction bands, linearised: none (the model gives no exact sensitivities for the "
                           "identified parameters, or the covariance could not be computed).\n\n")
             : fmt::format("Prediction bands, linearised (the covariance of the identified values carried by the "
                           "model's exact sensitivities, plus each point's own sigma): the {:g} % interval holds {} of "
                           "{} held-out points ({:.1f} %) and {} of {} fitted points ({:.1f} %); columns band_1sigma, "
                           "band_lower and band_upper of `fitted_points.csv`.\n\n",
                           level, held.covered, held.points, 100.0 * held.share(), fitted.covered, fitted.points,
                           100.0 * fitted.share()));
  if (!o.posterior) return;
  const PosteriorSummary& p = *o.posterior;
  std::vector<FitPoint> sampled = o.after;
  for (FitPoint& q : sampled) q.band = q.sampled_band;
  const BandCoverage sh = band_coverage(sampled, true, o.spec.band_level);
  md << fmt::format(
      "Posterior sampled (affine-invariant ensemble, {} walkers x {} steps, {} kept, {} model runs, "
      "{:.1f} s): acceptance {:.3f}, autocorrelation times {:.3g} steps; its {:g} % interval holds {} of "
      "{} held-out points (columns sampled_band_*, from {} samples).{}\n\n",
      p.walkers, p.steps, p.kept_steps, p.evaluations, p.seconds, p.acceptance,
      fmt::join(p.autocorrelation_steps, ", "), level, sh.covered, sh.points, p.predictions,
      p.warning.empty() ? "" : " **" + p.warning + "**");
  md << "| parameter | identified | linearised sigma | posterior mean | posterior sigma |\n|---|---|---|---|---|\n";
  for (size_t i = 0; i < o.values.size() && i < p.mean.size(); ++i)
    md << fmt::format("| `{}` | {:.6g} | {:.3g} | {:.6g} | {:.3g} |\n", o.spec.parameters[i].path, o.values[i],
                      o.std_devs[i], p.mean[i], p.std_dev[i]);
  md << '\n';
}

}  // namespace

void write_calibration_outputs(const CalibrationOutcome& o, const fs::path& case_file, double wall_seconds,
                               const fs::path& out_dir, bool plots) {
  fs::create_directories(out_dir);
  fs::remove(out_dir / "report.md");
  write_calibration_files(o, case_file, out_dir);
  std::ofstream md = open_out(out_dir / "report.md");
  md << fmt::format("# Calibration of `{}`\n\n", case_file.string());
  md << fmt::format(
      "{} in {:.1f} s, {} model evaluations ({:.2f} s each on average). Cost {:.6g} -> {:.6g}; rms residual {:.3g} -> "
      "{:.3g} sigma.\n\n",
      o.converged ? "Converged" : "**Not converged**", wall_seconds, o.residual_evaluations,
      wall_seconds / std::max(1, o.residual_evaluations), o.initial_cost, o.final_cost, rms_residual(o.before),
      rms_residual(o.after));
  md << fmt::format("Jacobian: {}.\n\n", o.derivatives);
  md << "Residuals: (computed - measured) / sigma per fitted point (for a check entry, sigma is relative to the "
        "reference). Loss: "
     << o.spec.loss << ".\n\n";
  md << fmt::format(
      "Reduced chi-square at the optimum: {:.3g}{}.\n\n", o.reduced_chi_square,
      o.reduced_chi_square > 1 ? " (above 1: the standard deviations below are scaled up by its square root)" : "");
  md << "| fitted set | points | rms residual at start | rms residual identified |\n|---|---|---|---|\n";
  for (const std::string& set : sets_of(o.after)) {
    const auto n = std::count_if(o.after.begin(), o.after.end(), [&](const FitPoint& p) { return p.set == set; });
    md << fmt::format("| {} | {} | {:.3g} | {:.3g} |\n", set, n, rms_residual(o.before, set),
                      rms_residual(o.after, set));
  }
  md << '\n';
  if (const std::vector<std::string> held = sets_of(o.after, true); !held.empty()) {
    md << "Held-out curves (cross-validation: predicted with the identified values, not fitted):\n\n"
          "| held-out set | points | rms residual at start | rms residual identified | largest relative error "
          "identified |\n|---|---|---|---|---|\n";
    for (const std::string& set : held) {
      const auto n = std::count_if(o.after.begin(), o.after.end(), [&](const FitPoint& p) { return p.set == set; });
      md << fmt::format("| {} | {} | {:.3g} | {:.3g} | {:.3g} % |\n", set, n, rms_residual(o.before, set),
                        rms_residual(o.after, set), 100.0 * largest_relative_misfit(o.after, set));
    }
    md << '\n';
    write_band_summary(o, md);
  }
  if (!o.spec.fit_checks.empty()) {
    md << "| fitted check | sigma (relative) |\n|---|---|\n";
    for (const std::string& name : o.spec.fit_checks)
      md << fmt::format("| {} | {:g} |\n", name, uncertainty_of(o.spec, name));
    md << '\n';
  }
  for (const CalibrationData& d : o.spec.data)
    md << fmt::format(
        "Data set `{}`: {} file `{}` ({} rows), {} table `{}`{}.\n\n", d.name, data_kind_name(d.data.kind),
        d.data.file.filename().string(), d.data.rows(), d.held_out ? "held out, predicted by" : "fitted to", d.table,
        d.data.derivative == 0 ? std::string()
        : !d.data.has("amplitude")
            ? fmt::format("; its phases, of the {}, moved by -{} deg to the displacement's",
                          d.data.derivative == 1 ? "velocity" : "acceleration", 90 * d.data.derivative)
            : fmt::format("; its {} amplitudes (in {}) read as displacement, each row divided by "
                          "(2 pi f)^{} and its phase moved by -{} deg",
                          d.data.derivative == 1 ? "velocity" : "acceleration", d.data.units.at("amplitude").symbol,
                          d.data.derivative, 90 * d.data.derivative));
  const bool any_linear =
      std::any_of(o.spec.parameters.begin(), o.spec.parameters.end(),
                  [](const CalibrationParameter& p) { return p.scale == CalibrationParameter::Scale::linear; });
  const std::string fit_space =
      any_linear ? "the fit values: log, and value / (upper - lower) for the parameters marked linear" : "log space";
  if (o.starts.size() > 1) {
    md << fmt::format(
        "## Starts\n\n{} starts (the case's values, then a Latin hypercube in {}, seed {}); start {} is "
        "reported.\n\n",
        o.starts.size(), fit_space, o.spec.seed, o.best + 1);
    md << "| start | converged | cost at start | final cost | iterations |\n|---|---|---|---|---|\n";
    for (size_t s = 0; s < o.starts.size(); ++s)
      md << fmt::format("| {} | {} | {:.6g} | {:.6g} | {} |\n", s + 1, o.starts[s].converged ? "yes" : "no",
                        o.starts[s].initial_cost, o.starts[s].final_cost, o.starts[s].iterations);
    md << "\nValues at every start and end: `starts.csv`.\n\n";
  }
  md << "## Parameters\n\n| parameter | start | identified | std (1 sigma) | lower | upper "
        "|\n|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < o.values.size(); ++i) {
    const auto& p = o.spec.parameters[i];
    md << fmt::format("| `{}`{} | {:.6g} | {:.6g} | {} | {:.6g} | {:.6g} |\n", p.path,
                      p.scale == CalibrationParameter::Scale::linear ? " (linear)" : "", p.start, o.values[i],
                      std::isnan(o.std_devs[i]) ? std::string("not identified") : fmt::format("{:.3g}", o.std_devs[i]),
                      p.lower, p.upper);
  }
  if (o.correlation.size() > 0) {
    md << "\nCorrelation matrix:\n\n|   |";
    for (size_t j = 0; j < o.values.size(); ++j) md << fmt::format(" {} |", j + 1);
    md << "\n|---|";
    for (size_t j = 0; j < o.values.size(); ++j) md << "---|";
    md << '\n';
    for (Eigen::Index i = 0; i < o.correlation.rows(); ++i) {
      md << fmt::format("| {} |", i + 1);
      for (Eigen::Index j = 0; j < o.correlation.cols(); ++j)
        md << (std::isnan(o.correlation(i, j)) ? std::string(" - |") : fmt::format(" {:+.3f} |", o.correlation(i, j)));
      md << '\n';
    }
  }
  if (!o.weakest_profile.empty()) {
    md << fmt::format("\n## Weakest direction\n\nThe cost along the covariance's largest axis ({}:",
                      any_linear ? "fit values" : "log values");
    for (size_t i = 0; i < o.weakest_direction.size(); ++i)
      md << fmt::format("{} {:+.3f} `{}`", i ? "," : "", o.weakest_direction[i], o.spec.parameters[i].path);
    md << "), t standard deviations from the optimum; a quadratic cost rises as predicted.\n\n| t |";
    for (const auto& p : o.spec.parameters) md << fmt::format(" `{}` |", p.path);
    md << " cost rise | predicted |\n|---|";
    for (size_t i = 0; i < o.spec.parameters.size(); ++i) md << "---|";
    md << "---|---|\n";
    for (const auto& pt : o.weakest_profile) {
      md << fmt::format("| {:+g} |", pt.t);
      for (double v : pt.values) md << fmt::format(" {:.6g} |", v);
      md << fmt::format(" {:.4g} | {:.4g} |\n", pt.rise, pt.predicted);
    }
  }
  if (!o.warnings.empty()) {
    md << "\n## Warnings\n\n";
    for (const auto& w : o.warnings) md << "- " << w << '\n';
  }
  if (!o.cross_check.empty() || !o.spec.cross_check.empty()) {
    md << fmt::format("\n## Cross-check: `{}` with the identified values\n\n{} ({:.1f} s).\n\n",
                      o.spec.cross_check.filename().string(),
                      !o.cross_check_failure.empty() ? "**No solution: the checks have no verdict**"
                      : o.cross_check_passed()       ? "Every check passes"
                                                     : "**Some checks fail**",
                      o.cross_check_seconds);
    if (!o.cross_check_failure.empty()) md << o.cross_check_failure << "\n\n";
    md << "| check entry | computed | reference | error | tolerance | pass |\n|---|---|---|---|---|---|\n";
    for (const CheckEntry& e : o.cross_check)
      md << fmt::format("| {} | {:.6g} | {:.6g} | {:.3g} | {:.3g} | {} |\n", e.name, e.computed, e.reference,
                        e.abs_error, e.tolerance, e.pass ? "yes" : "**no**");
    if (!o.cross_check_tables.empty())
      md << fmt::format(
          "\nIts result tables at the identified values: `cross_check/*.csv`{}.\n",
          o.spec.cross_check_bands
              ? ", beside every column the parameters move a `<column>_band_1sigma` (the parameters' covariance "
                "carried by central differences, 1e-4 both ways in each parameter's fit variable)"
              : "");
  }
  if (plots && !o.spec.data.empty()) {
    md << "\n## Fitted curves over the data\n\n";
    for (const CalibrationData& d : o.spec.data)
      for (const auto& [column, result] : d.columns) {
        const std::string& quantity = column;  // clang 14 cannot capture a structured binding (P1091)
        const bool fitted = std::any_of(o.after.begin(), o.after.end(),
                                        [&](const FitPoint& p) { return p.set == d.name && p.quantity == quantity; });
        if ((column == "force" && !fitted) || (column == "frequency" && d.data.kind != DataKind::peaks) ||
            column == "relative_displacement" || (column == "amplitude" && !fitted))
          continue;
        const Plot p = plot_data_set(o, d, column, out_dir);
        md << (p.file.empty() ? fmt::format("- {}: not drawn ({})\n", p.title, p.note)
                              : fmt::format("![{}]({})\n\n", p.title, p.file));
      }
  }
  md << "\n## Fitted points\n\n(Points of held-out sets are predicted, not fitted.)\n\n| set | point | unit | measured "
        "| "
        "sigma | at start | residual | identified | residual |\n|---|---|---|---|---|---|---|---|---|\n";
  for (size_t k = 0; k < o.after.size() && k < o.before.size(); ++k) {
    const FitPoint& b = o.before[k];
    const FitPoint& a = o.after[k];
    const double u = a.display_scale();
    md << fmt::format("| {} | {} | {} | {:.6g} | {:.3g} | {:.6g} | {:+.2f} | {:.6g} | {:+.2f} |\n", a.set, a.label,
                      a.unit.empty() ? "-" : a.unit, a.measured * u, a.sigma * u, b.computed * u, b.residual(),
                      a.computed * u, a.residual());
  }
  md << fmt::format(
      "\nSolver: {}\n\nFiles: `identification.csv`, `convergence.csv`, `starts.csv`, `fitted_points.csv`{}.\n",
      o.termination,
      o.converged ? ", `calibrated.toml`"
                  : ", `restart.toml` (no `calibrated.toml`: the fit did not converge; `calibrate --restart-from "
                    "restart.toml` continues it)");
  md.close();
  if (!md) throw std::runtime_error("failed writing the calibration report");
  write_html_twin(out_dir / "report.md");
}

}  // namespace bb
