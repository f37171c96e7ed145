#include "report/frf_plots.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/gnuplot.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

// Title and axes of an amplitude-vs-frequency plot (log amplitude).
std::string amplitude_axes(const std::string& title) {
  return fmt::format(
      "set title '{}'\nset logscale y\nset format y '10^{{%L}}'\nset xlabel 'frequency [Hz]'\n"
      "set ylabel 'amplitude [m]'\nset grid\nset key outside right\n",
      gnuplot_quote(title));
}

}  // namespace

Plot plot_frf(const FrfOutcome& frf, const std::string& output, const fs::path& out_dir, const std::string& stem) {
  std::vector<std::pair<std::string, Eigen::Index>> curves;  // model, sweep column
  for (const FrfCurveSet& c : frf.curves)
    for (size_t i = 0; i < c.outputs.size(); ++i)
      if (c.outputs[i] == output) curves.emplace_back(c.model, c.first_column + static_cast<Eigen::Index>(i));
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# frequency_hz";
    for (const auto& [model, col] : curves) out << ' ' << model << "_amplitude_m";
    out << '\n';
    for (size_t k = 0; k < frf.sweep.frequency_hz.size(); ++k) {
      out << frf.sweep.frequency_hz[k];
      for (const auto& [model, col] : curves)
        out << ' ' << std::abs(frf.sweep.response(static_cast<Eigen::Index>(k), col));
      out << '\n';
    }
  }
  const std::string title = fmt::format("Response {} (amplitude)", output);
  std::string script = amplitude_axes(title);
  const double f0 = frf.sweep.frequency_hz.front(), f1 = frf.sweep.frequency_hz.back();
  script += fmt::format("set xrange [{}:{}]\n", f0, f1);
  if (frf.full_modal)
    for (Eigen::Index k = 0; k < frf.full_modal->frequencies_hz.size(); ++k) {
      const double f = frf.full_modal->frequencies_hz[k];
      if (f >= f0 && f <= f1)
        script += fmt::format("set arrow from {},graph 0 to {},graph 1 nohead dt 3 lc rgb '#bbbbbb'\n", f, f);
    }
  script += "plot ";
  for (size_t i = 0; i < curves.size(); ++i)
    script += fmt::format("{}'{}.dat' using 1:{} with lines lw {} lc rgb '{}' title '{}'", i ? ", \\\n     " : "", stem,
                          i + 2, i == 0 ? 2 : 1, series_colour(i), gnuplot_quote(curves[i].first));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_force_levels(const FrfOutcome& frf, const fs::path& out_dir, const std::string& stem) {
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# frequency_hz, amplitude [m] at each force level\n";
    for (size_t k = 0; k < frf.sweep.frequency_hz.size(); ++k) {
      out << frf.sweep.frequency_hz[k];
      for (const Eigen::VectorXd& a : frf.level_amplitudes) out << ' ' << a[static_cast<Eigen::Index>(k)];
      out << '\n';
    }
  }
  const FrfCurveSet& first = frf.curves.front();
  const std::string title = fmt::format("Response {} ({}) at each force level", first.outputs.front(), first.model);
  std::string script = amplitude_axes(title) + "plot ";
  for (size_t i = 0; i < frf.level_forces.size(); ++i)
    script += fmt::format("{}'{}.dat' using 1:{} with lines title 'Fe = {:g} N'", i ? ", \\\n     " : "", stem, i + 2,
                          frf.level_forces[i]);
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_rom_study(const ResultTable& study, const fs::path& out_dir, const std::string& stem) {
  const std::vector<std::string>& sets = study.text.front();
  std::vector<std::string> names;
  for (const std::string& s : sets)
    if (std::find(names.begin(), names.end(), s) == names.end()) names.push_back(s);
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# one block per master set: modes max_freq_error peak_freq_error (errors floored at 1e-9 for the log "
           "scale)\n";
    for (const std::string& name : names) {
      out << "# " << name << '\n';
      for (Eigen::Index r = 0; r < study.values.rows(); ++r)
        if (sets[static_cast<size_t>(r)] == name)
          out << study.values(r, 2) << ' ' << std::max(study.values(r, 4), 1e-9) << ' '
              << std::max(study.values(r, 6), 1e-9) << '\n';
      out << "\n\n";
    }
  }
  const std::string title = "Reduced model error vs fixed-interface modes";
  std::string script = "set title '" + title +
                       "'\nset logscale y\nset format y '10^{%L}'\nset xlabel 'fixed-interface modes'\n"
                       "set ylabel 'relative error'\nset grid\nset key outside right\nplot ";
  for (size_t i = 0; i < names.size(); ++i)
    script += fmt::format(
        "{}'{}.dat' index {} using 1:2 with linespoints pt 7 title '{}: max error, first frequencies', "
        "'{}.dat' index {} using 1:3 with linespoints pt 5 dt 2 title '{}: FRF peak frequency'",
        i ? ", \\\n     " : "", stem, i, gnuplot_quote(names[i]), stem, i, gnuplot_quote(names[i]));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
