#include "report/rotating_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/gnuplot.hpp"

namespace bb {

namespace fs = std::filesystem;

Plot plot_rotating_history(const RotatingOutcome& o, const ResultTables& tables, size_t set, int direction,
                           const fs::path& out_dir, const std::string& stem, double zoom) {
  const char axis = "xyz"[direction];
  const std::string name = o.history_sets.at(set);
  const ResultTable& d = tables.at("deflection");
  const auto static_column = d.column_index(fmt::format("static_u{}_m", axis));
  {
    // The whole run from histories.csv's rows; a zoom from every step.
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# time_s u_m\n";
    if (zoom > 0) {
      const Eigen::Index c = static_cast<Eigen::Index>(set) * o.dim + direction;
      for (size_t i = 0; i < o.history.time.size() && o.history.time[i] <= zoom; ++i)
        out << o.history.time[i] << ' ' << o.set_histories(static_cast<Eigen::Index>(i), c) << '\n';
    } else {
      const ResultTable& h = tables.at("histories");
      const auto column = h.column_index(fmt::format("{}.u{}_m", name, axis));
      for (Eigen::Index i = 0; i < h.values.rows(); ++i) out << h.values(i, 1) << ' ' << h.values(i, *column) << '\n';
    }
  }
  const double steady = d.values(static_cast<Eigen::Index>(set), *static_column);
  const std::string title = fmt::format("Node set '{}': {} displacement in the rotating frame ({}){}", name, axis,
                                        o.profile, zoom > 0 ? fmt::format(", first {:g} s", zoom) : "");
  const std::string script = fmt::format(
      "set title '{}'\nset xlabel 'time [s]'\nset ylabel 'u_{} [m]'\nset grid\nset key bottom right\n{}"
      "plot '{}.dat' using 1:2 with lines lc rgb '#1f5fbf' title 'u_{}', {:.12g} with lines dt 2 lc rgb '#bf1f1f' "
      "title 'steady "
      "centrifugal deflection'\n",
      gnuplot_quote(title), axis, zoom > 0 ? fmt::format("set xrange [0:{:g}]\n", zoom) : "", stem, axis, steady);
  return draw(out_dir, stem, title, script);
}

Plot plot_campbell(const RotatingOutcome& o, const std::vector<int>& engine_orders, const fs::path& out_dir,
                   const std::string& stem) {
  const ffrf::CampbellDiagram& c = o.campbell;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (Eigen::Index m = 0; m < c.frequencies_hz.cols(); ++m) {
      out << "# mode " << m + 1 << ": omega_rad_s frequency_hz\n";
      for (size_t i = 0; i < c.speeds.size(); ++i)
        out << c.speeds[i] << ' ' << c.frequencies_hz(static_cast<Eigen::Index>(i), m) << '\n';
      out << "\n\n";
    }
    out << "# engine-order crossings: speed_rad_s frequency_hz engine_order\n";
    for (const ffrf::EngineOrderCrossing& x : o.crossings)
      out << x.speed << ' ' << x.frequency_hz << ' ' << x.engine_order << '\n';
    if (o.crossings.empty()) out << "nan nan nan\n";
  }
  const double top = c.speeds.empty() ? 1.0 : c.speeds.back();
  // Up to the third mode (or the highest engine-order line, if higher): the crossings a designer reads.
  double f_top = 0.0;
  for (int eo : engine_orders) f_top = std::max(f_top, eo * top / (2 * 3.141592653589793));
  if (c.frequencies_hz.size() > 0)
    f_top = std::max(f_top, c.frequencies_hz.col(std::min<Eigen::Index>(2, c.frequencies_hz.cols() - 1)).maxCoeff());
  const std::string title = "Campbell diagram: rotating modes (lines) and engine-order lines (dashed)";
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'speed [rad/s]'\nset ylabel 'frequency [Hz]'\nset grid\nset key outside right\n"
      "set xrange [0:{:.12g}]\nset yrange [0:{:.12g}]\nset datafile missing 'nan'\nplot ",
      gnuplot_quote(title), top, 1.15 * f_top);
  for (Eigen::Index m = 0; m < c.frequencies_hz.cols(); ++m)
    script += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints pt 7 ps 0.4 title 'mode {}'",
                          m ? ", \\\n     " : "", stem, m, m + 1);
  script +=
      fmt::format(", \\\n     '{}.dat' index {} using 1:2 with points pt 6 ps 1.2 lc rgb 'black' title 'crossings'",
                  stem, c.frequencies_hz.cols());
  // Engine-order lines f = EO Omega / 2 pi.
  for (int eo : engine_orders)
    script += fmt::format(", \\\n     {} * x / (2 * pi) with lines dt 2 lc rgb '#7f7f7f' notitle", eo);
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_rotating_fidelity(const ResultTable& study, const fs::path& out_dir, const std::string& stem) {
  const auto col = [&](const char* name) { return *study.column_index(name); };
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# seconds error (floored at 1e-12) level: one block per error kind (mean, motion, frequency)\n";
    for (const char* kind : {"mean_error", "motion_error", "frequency_error"}) {
      for (Eigen::Index r = 0; r < study.values.rows(); ++r) {
        const double e = study.values(r, col(kind));
        if (std::isfinite(e))
          out << study.values(r, col("seconds")) << ' ' << std::max(e, 1e-12) << ' ' << study.values(r, col("level"))
              << '\n';
      }
      out << "\n\n";
    }
  }
  const std::string title = "Rotating scene: error of each model level against the finest vs cost (labels: level)";
  const std::string script = fmt::format(
      "set title '{0}'\nset logscale xy\nset format y '10^{{%L}}'\nset xlabel 'wall time [s]'\nset ylabel 'relative "
      "error'\nset grid\n"
      "set key outside right\nset datafile missing 'nan'\n"
      "plot '{1}.dat' index 0 using 1:2 with points pt 7 title 'steady deflection', '{1}.dat' index 0 using "
      "1:2:(sprintf('%d', $3)) with "
      "labels offset 0,1 notitle, \\\n     '{1}.dat' index 1 using 1:2 with points pt 5 title 'largest motion', \\\n"
      "     '{1}.dat' index 2 using 1:2 with points pt 9 title 'first rotating frequency'\n",
      gnuplot_quote(title), stem);
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
