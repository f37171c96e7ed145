#include "report/nonlinear_mode_plots.hpp"

#include <fmt/format.h>

#include "report/gnuplot.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

// The amplitude column of the nonlinear_modes table drawn for mode m, and its legend.
std::string amplitude_column(const HbmOutcome& hbm, const NonlinearModesSpec& nm, size_t m) {
  if (!nm.peaks.empty() && nm.peaks[m] != "peak") return nm.peaks[m] + "_component_m";
  return hbm.prepared.response_names.front() + "_amp_m";
}
std::string amplitude_legend(const HbmOutcome& hbm, const NonlinearModesSpec& nm, size_t m) {
  if (!nm.peaks.empty() && nm.peaks[m] != "peak") return nm.peaks[m] == "ip" ? "IP component" : "OOP component";
  return hbm.prepared.response_names.front();
}

}  // namespace

Plot plot_backbones(const HbmOutcome& hbm, const HbmSpec& spec, const ResultTable& t, const fs::path& out_dir,
                    const std::string& stem) {
  const NonlinearModesSpec& nm = *spec.nonlinear_modes;
  const int mode = *t.column_index("mode"), hz = *t.column_index("frequency_hz");
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t m = 0; m < nm.linear_modes.size(); ++m) {
      const int amp = *t.column_index(amplitude_column(hbm, nm, m));
      out << "# backbone of linear mode " << nm.linear_modes[m] << ": frequency_hz amplitude_m\n";
      for (Eigen::Index i = 0; i < t.values.rows(); ++i)
        if (t.values(i, mode) == nm.linear_modes[m]) out << t.values(i, hz) << ' ' << t.values(i, amp) << '\n';
      out << "\n\n";
    }
    out << "# the sweep's peaks: frequency_hz component_m, per level and peak kind\n";
    for (const HbmLevel& l : hbm.levels)
      for (const HbmPeak& pk : l.peaks) out << pk.frequency_hz << ' ' << pk.component << '\n';
  }
  const std::string title = "Backbones of the nonlinear modes (EPMC) and the forced-response peaks";
  std::string script = fmt::format(
      "set title '{}'\nset logscale y\nset format y '10^{{%L}}'\nset xlabel 'frequency [Hz]'\n"
      "set ylabel 'amplitude [m]'\nset grid\nset key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t m = 0; m < nm.linear_modes.size(); ++m)
    script += fmt::format("{}'{}.dat' index {} using 1:2 with lines lw 2 lc rgb '{}' title 'mode {} ({})' noenhanced",
                          m ? ", \\\n     " : "", stem, m, series_colour(m), nm.linear_modes[m],
                          gnuplot_quote(amplitude_legend(hbm, nm, m)));
  script +=
      fmt::format(", \\\n     '{}.dat' index {} using 1:2 with points pt 7 lc rgb '#000000' title 'sweep peaks'\n",
                  stem, nm.linear_modes.size());
  return draw(out_dir, stem, title, script);
}

Plot plot_modal_damping(const HbmOutcome& hbm, const fs::path& out_dir, const std::string& stem) {
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (const hbm::NonlinearModeBranch& b : hbm.nonlinear_modes) {
      out << "# linear mode " << b.linear_mode << ": modal_amplitude damping_ratio\n";
      for (const hbm::NonlinearModePoint& p : b.points) out << p.modal_amplitude << ' ' << p.damping_ratio() << '\n';
      out << "\n\n";
    }
  }
  const std::string title = "Modal damping ratio of the nonlinear modes against the modal amplitude";
  std::string script = fmt::format(
      "set title '{}'\nset logscale x\nset format x '10^{{%L}}'\nset xlabel 'modal amplitude [m kg^{{1/2}}]'\n"
      "set ylabel 'damping ratio'\nset grid\nset key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t m = 0; m < hbm.nonlinear_modes.size(); ++m)
    script += fmt::format("{}'{}.dat' index {} using 1:2 with lines lw 2 lc rgb '{}' title 'mode {}'",
                          m ? ", \\\n     " : "", stem, m, series_colour(m), hbm.nonlinear_modes[m].linear_mode);
  script += '\n';
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
