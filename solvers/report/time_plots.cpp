#include "report/time_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "report/gnuplot.hpp"

namespace bb {

namespace fs = std::filesystem;

Plot plot_time_frf(const TimeOutcome& time, size_t response, const fs::path& out_dir, const std::string& stem) {
  const std::string name = time.prepared.response_names.at(response);
  const auto r = static_cast<Eigen::Index>(response);
  bool hbm = false;
  std::vector<bool> envelope(time.levels.size(), false);  // a level with a point that does not repeat
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t k = 0; k < time.levels.size(); ++k) {
      const TimeLevel& l = time.levels[k];
      out << "# Fe = " << l.force
          << " N, time integration: frequency_hz amplitude linear_amplitude, and where the motion is not "
             "steady the range of its first harmonic over the last periods: envelope_min envelope_max\n";
      for (size_t i = 0; i < l.frequency_hz.size(); ++i) {
        const auto f = static_cast<Eigen::Index>(i);
        const bool open = !l.steady[i] && l.envelope_min.rows() > f && std::isfinite(l.envelope_min(f, r));
        envelope[k] = envelope[k] || open;
        out << l.frequency_hz[i] << ' ' << l.amplitude(f, r) << ' ' << l.linear(f, r) << ' '
            << (open ? l.envelope_min(f, r) : NAN) << ' ' << (open ? l.envelope_max(f, r) : NAN) << '\n';
      }
      out << "\n\n# harmonic balance: frequency_hz amplitude\n";
      if (l.hbm) {
        hbm = true;
        for (size_t i = 0; i < l.hbm->frequency_hz.size(); ++i)
          out << l.hbm->frequency_hz[i] << ' ' << l.hbm->amplitude(static_cast<Eigen::Index>(i), r) << '\n';
      } else {
        out << "nan nan\n";
      }
      out << "\n\n";
    }
  }
  const std::string title =
      fmt::format("Response {}: time integration (points), harmonic balance and linear model (lines)", name);
  std::string script = fmt::format(
      "set title '{}'\nset logscale y\nset format y '10^{{%L}}'\nset xlabel 'frequency [Hz]'\n"
      "set ylabel 'amplitude [m]'\nset grid\nset key outside right\nset datafile missing 'nan'\nplot ",
      gnuplot_quote(title));
  for (size_t i = 0; i < time.levels.size(); ++i) {
    // The ranges first: gnuplot blanks the area around an error bar's centre, which would hide the points.
    if (envelope[i])
      script += fmt::format(
          "{}'{}.dat' index {} using 1:2:4:5 with yerrorbars pt 7 ps 0 lc rgb '{}' title 'Fe = {:g} N, not periodic: "
          "first-harmonic range', \\\n     ",
          i ? ", \\\n     " : "", stem, 2 * i, series_colour(i), time.levels[i].force);
    script += fmt::format(
        "{}'{}.dat' index {} using 1:2 with points pt 7 ps 0.5 lc rgb '{}' title 'Fe = {:g} N, time domain'",
        i && !envelope[i] ? ", \\\n     " : "", stem, 2 * i, series_colour(i), time.levels[i].force);
    if (hbm)
      script += fmt::format(", \\\n     '{}.dat' index {} using 1:2 with lines lc rgb '{}' title 'Fe = {:g} N, HBM'",
                            stem, 2 * i + 1, series_colour(i), time.levels[i].force);
    script += fmt::format(
        ", \\\n     '{}.dat' index {} using 1:3 with lines dt 2 lc rgb '{}' title 'Fe = {:g} N, linear (contacts as "
        "springs)'",
        stem, 2 * i, series_colour(i), time.levels[i].force);
  }
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_hysteresis(const TimeOutcome& time, const fs::path& out_dir, const std::string& stem) {
  const timeint::TimeHistory& h = time.record->history;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t c = 0; c < h.contacts.size(); ++c) {
      out << "# " << time.prepared.contact_names[c] << ": u [m] T [N]\n";
      for (const timeint::ContactSample& s : h.contacts[c]) out << s.u << ' ' << s.tangential << '\n';
      out << "\n\n";
    }
  }
  const std::string title =
      fmt::format("Hysteresis loops at {:g} Hz, Fe = {:g} N", time.record->frequency_hz, time.record->force);
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'relative tangential displacement u [m]'\nset ylabel 'tangential force T [N]'\n"
      "set grid\nset key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t c = 0; c < h.contacts.size(); ++c)
    script +=
        fmt::format("{}'{}.dat' index {} using 1:2 with lines lw 2 lc rgb '{}' title '{}'", c ? ", \\\n     " : "",
                    stem, c, series_colour(c), gnuplot_quote(time.prepared.contact_names[c]));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_contact_forces(const TimeOutcome& time, const fs::path& out_dir, const std::string& stem) {
  const timeint::TimeHistory& h = time.record->history;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t c = 0; c < h.contacts.size(); ++c) {
      out << "# " << time.prepared.contact_names[c] << ": t [s] N [N] T [N]\n";
      for (size_t i = 0; i < h.contacts[c].size(); ++i)
        out << h.time[i] << ' ' << h.contacts[c][i].normal << ' ' << h.contacts[c][i].tangential << '\n';
      out << "\n\n";
    }
  }
  const std::string title = fmt::format("Contact forces at {:g} Hz, Fe = {:g} N (N solid, T dashed)",
                                        time.record->frequency_hz, time.record->force);
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'time [s]'\nset ylabel 'force [N]'\nset grid\nset key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t c = 0; c < h.contacts.size(); ++c)
    script += fmt::format(
        "{0}'{1}.dat' index {2} using 1:2 with lines lw 2 lc rgb '{3}' title '{4} N', "
        "'{1}.dat' index {2} using 1:3 with lines dt 2 lc rgb '{3}' title '{4} T'",
        c ? ", \\\n     " : "", stem, c, series_colour(c), gnuplot_quote(time.prepared.contact_names[c]));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_time_step_study(const ResultTable& study, const fs::path& out_dir, const std::string& stem) {
  const int col_n = *study.column_index("steps_per_period"), col_t = *study.column_index("steady_tolerance");
  const int col_e = *study.column_index("max_amp_error"), col_s = *study.column_index("seconds");
  std::vector<double> tolerances;
  for (Eigen::Index r = 0; r < study.values.rows(); ++r)
    if (std::find(tolerances.begin(), tolerances.end(), study.values(r, col_t)) == tolerances.end())
      tolerances.push_back(study.values(r, col_t));
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# one block per steady-state tolerance: seconds max_amp_error (floored at 1e-12) steps_per_period\n";
    for (double tol : tolerances) {
      for (Eigen::Index r = 0; r < study.values.rows(); ++r)
        if (study.values(r, col_t) == tol)
          out << study.values(r, col_s) << ' ' << std::max(study.values(r, col_e), 1e-12) << ' '
              << study.values(r, col_n) << '\n';
      out << "\n\n";
    }
  }
  const std::string title = "Time integration: largest FRF amplitude error against the finest variant vs cost";
  std::string script = fmt::format(
      "set title '{}'\nset logscale xy\nset format y '10^{{%L}}'\nset xlabel 'sweep time [s]'\n"
      "set ylabel 'max |relative amplitude error|'\nset grid\nset key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t i = 0; i < tolerances.size(); ++i)
    script += fmt::format(
        "{0}'{1}.dat' index {2} using 1:2 with linespoints pt 7 lc rgb '{3}' title 'steady tolerance {4:g}', "
        "'{1}.dat' index {2} using 1:2:(sprintf('%d', $3)) with labels offset 0,1 notitle",
        i ? ", \\\n     " : "", stem, i, series_colour(i), tolerances[i]);
  script += '\n';
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
