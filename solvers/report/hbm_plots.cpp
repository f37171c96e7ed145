#include "report/hbm_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "checks/checks.hpp"
#include "common/errors.hpp"
#include "report/gnuplot.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

// The abscissa of the performance plots: CF / Fe with a damper, Fe otherwise.
double abscissa(const HbmOutcome& hbm, double force) {
  return hbm.prepared.damper ? hbm.prepared.centrifugal_force / force : force;
}

std::string abscissa_label(const HbmOutcome& hbm) { return hbm.prepared.damper ? "CF / Fe" : "Fe [N]"; }

}  // namespace

Plot plot_hbm_levels(const HbmOutcome& hbm, size_t response, bool per_newton, const fs::path& out_dir,
                     const std::string& stem) {
  const std::string name = hbm.prepared.response_names.at(response);
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (const HbmLevel& l : hbm.levels) {
      // Column 2 holds the stable points (solid), column 3 the unstable ones and their neighbours
      // (dashed, so that the two join); without a stability analysis every point is in column 2.
      out << "# Fe = " << l.force << " N: frequency_hz amplitude_stable amplitude_unstable\n";
      const auto unstable = [&](size_t i) { return i < l.stable.size() && l.stable[i] == 0.0; };
      for (size_t i = 0; i < l.frequency_hz.size(); ++i) {
        const double a = l.amplitude(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(response)) /
                         (per_newton ? l.force : 1.0);
        const bool near_unstable = unstable(i) || (i > 0 && unstable(i - 1)) || unstable(i + 1);
        out << l.frequency_hz[i] << ' ';
        if (unstable(i))
          out << "nan ";
        else
          out << a << ' ';
        if (near_unstable)
          out << a;
        else
          out << "nan";
        out << '\n';
      }
      out << "\n\n";
    }
    if (per_newton) {
      out << "# linear limits per newton: frequency_hz free stuck\n";
      for (Eigen::Index i = 0; i < hbm.limit_frequency_hz.size(); ++i)
        out << hbm.limit_frequency_hz[i] << ' ' << hbm.free_response(i, static_cast<Eigen::Index>(response)) << ' '
            << hbm.stuck_response(i, static_cast<Eigen::Index>(response)) << '\n';
    }
  }
  const std::string title =
      per_newton ? fmt::format("Response {} per newton at each force level, with the linear limits", name)
                 : fmt::format("Response {} at each force level (first harmonic)", name);
  std::string script = fmt::format(
      "set title '{}'\nset logscale y\nset format y '10^{{%L}}'\nset xlabel 'frequency [Hz]'\n"
      "set ylabel '{}'\nset grid\nset key outside right\nplot ",
      gnuplot_quote(title), per_newton ? "amplitude / Fe [m/N]" : "amplitude [m]");
  bool any_unstable = false;
  for (const HbmLevel& l : hbm.levels)
    for (double st : l.stable) any_unstable = any_unstable || st == 0.0;
  for (size_t i = 0; i < hbm.levels.size(); ++i) {
    script += fmt::format("{}'{}.dat' index {} using 1:2 with lines lc rgb '{}' title 'Fe = {:g} N'",
                          i ? ", \\\n     " : "", stem, i, series_colour(i), hbm.levels[i].force);
    if (any_unstable)
      script += fmt::format(", \\\n     '{}.dat' index {} using 1:3 with lines dt 2 lc rgb '{}' {}", stem, i,
                            series_colour(i), i == 0 ? "title 'unstable (Hill)'" : "notitle");
  }
  if (per_newton)
    script += fmt::format(
        ", \\\n     '{0}.dat' index {1} using 1:2 with lines lw 2 dt 2 lc rgb '#000000' title 'free (no damper)', \\\n"
        "     '{0}.dat' index {1} using 1:3 with lines lw 2 dt 3 lc rgb '#000000' title 'stuck (eq 3.51)'",
        stem, hbm.levels.size());
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_hbm_performance(const HbmOutcome& hbm, const std::string& quantity, const fs::path& reference,
                          const fs::path& out_dir, const std::string& stem) {
  const std::vector<std::string> kinds =
      hbm.prepared.ip_oop ? std::vector<std::string>{"ip", "oop"} : std::vector<std::string>{"peak"};
  std::vector<std::vector<double>> ref(kinds.size());
  std::vector<std::vector<long>> ref_keys(kinds.size());
  for (size_t k = 0; k < kinds.size() && !reference.empty(); ++k) {
    try {
      ReferenceColumn c = read_reference_column(reference, "level", kinds[k] + "_" + quantity);
      ref[k] = std::move(c.values);
      ref_keys[k] = std::move(c.keys);
    } catch (const InputError&) {
      // The reference need not give every peak kind or quantity: that curve is left out.
    }
  }
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# abscissa, then per peak kind: ours, reference (nan where none)\n";
    for (size_t l = 0; l < hbm.levels.size(); ++l) {
      const HbmLevel& level = hbm.levels[l];
      out << abscissa(hbm, level.force);
      for (size_t k = 0; k < kinds.size(); ++k) {
        const bool ok = k < level.peaks.size() && level.peaks[k].solution.converged;
        const double v = !ok                ? std::nan("")
                         : quantity == "hz" ? level.peaks[k].frequency_hz
                                            : level.peaks[k].amplitude / level.force;
        double r = std::nan("");
        for (size_t i = 0; i < ref_keys[k].size(); ++i)
          if (ref_keys[k][i] == static_cast<long>(l + 1)) r = ref[k][i];
        out << ' ' << v << ' ' << r;
      }
      out << '\n';
    }
  }
  const std::string what = quantity == "hz" ? "resonance frequency" : "resonance amplitude per newton";
  const std::string title = fmt::format("Damper performance: {} against {}", what, abscissa_label(hbm));
  std::string script = fmt::format(
      "set title '{}'\nset logscale x\nset xlabel '{}'\nset ylabel '{}'\nset grid\nset key outside right\n",
      gnuplot_quote(title), abscissa_label(hbm), quantity == "hz" ? "frequency [Hz]" : "amplitude / Fe [m/N]");
  if (quantity != "hz") script += "set logscale y\nset format y '10^{%L}'\n";
  script += "set datafile missing 'nan'\nplot ";
  for (size_t k = 0; k < kinds.size(); ++k) {
    std::string upper = kinds[k] == "peak" ? "peak" : kinds[k] == "ip" ? "IP" : "OOP";
    script += fmt::format("{}'{}.dat' using 1:{} with linespoints pt 7 lc rgb '{}' title '{} (bladebench)'",
                          k ? ", \\\n     " : "", stem, 2 + 2 * k, series_colour(k), upper);
    if (!ref[k].empty())
      script +=
          fmt::format(", \\\n     '{}.dat' using 1:{} with linespoints pt 4 dt 2 lc rgb '{}' title '{} (reference)'",
                      stem, 3 + 2 * k, series_colour(k), upper);
  }
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_contact_states(const HbmOutcome& hbm, const std::string& kind, const fs::path& out_dir,
                         const std::string& stem) {
  const std::vector<std::string>& contacts = hbm.prepared.contact_names;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# abscissa, then per contact: stick fraction, lift-off fraction of the period at the peak\n";
    for (const HbmLevel& level : hbm.levels) {
      const HbmPeak* peak = nullptr;
      for (const HbmPeak& p : level.peaks)
        if (p.kind == kind && p.solution.converged) peak = &p;
      if (!peak) continue;
      out << abscissa(hbm, level.force);
      for (const friction::AftResult& a : peak->solution.contacts) {
        double stick = 0, lift = 0;
        for (const friction::ContactState s : a.state) {
          stick += s == friction::ContactState::stick ? 1 : 0;
          lift += s == friction::ContactState::lift_off ? 1 : 0;
        }
        out << ' ' << stick / static_cast<double>(a.state.size()) << ' ' << lift / static_cast<double>(a.state.size());
      }
      out << '\n';
    }
  }
  const std::string title = fmt::format("Contact states at the {} peaks (slip = the rest of the period)", kind);
  std::string script = fmt::format(
      "set title '{}'\nset logscale x\nset xlabel '{}'\nset ylabel 'fraction of the period'\n"
      "set yrange [-0.02:1.02]\nset grid\nset key outside right\nplot ",
      gnuplot_quote(title), abscissa_label(hbm));
  for (size_t c = 0; c < contacts.size(); ++c)
    script += fmt::format(
        "{0}'{1}.dat' using 1:{2} with linespoints pt 7 lc rgb '{3}' title '{4} stick', \\\n"
        "     '{1}.dat' using 1:{5} with linespoints pt 4 dt 2 lc rgb '{3}' title '{4} lift-off'",
        c ? ", \\\n     " : "", stem, 2 + 2 * c, series_colour(c), gnuplot_quote(contacts[c]), 3 + 2 * c);
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_hbm_harmonics_study(const ResultTable& study, const fs::path& out_dir, const std::string& stem) {
  std::vector<std::string> kinds;
  for (const std::string& c : study.columns)
    if (c.ends_with("_amp_error")) kinds.push_back(c.substr(0, c.size() - 10));
  const int col_h = *study.column_index("harmonics"), col_f = *study.column_index("fe_n"),
            col_s = *study.column_index("seconds");
  std::vector<double> levels;
  for (Eigen::Index r = 0; r < study.values.rows(); ++r)
    if (std::find(levels.begin(), levels.end(), study.values(r, col_f)) == levels.end())
      levels.push_back(study.values(r, col_f));
  std::vector<std::string> titles;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# one block per level and peak kind: seconds |amplitude error| (floored at 1e-12) H\n";
    for (double f : levels)
      for (const std::string& k : kinds) {
        const int col_e = *study.column_index(k + "_amp_error");
        out << "# Fe = " << f << " N, " << k << '\n';
        for (Eigen::Index r = 0; r < study.values.rows(); ++r) {
          const double e = study.values(r, col_e);
          if (study.values(r, col_f) != f || !std::isfinite(e)) continue;
          out << study.values(r, col_s) << ' ' << std::max(std::abs(e), 1e-12) << ' ' << study.values(r, col_h) << '\n';
        }
        out << "\n\n";
        titles.push_back(fmt::format("Fe = {:g} N, {}", f, k));
      }
  }
  const std::string title = "Harmonic balance: peak amplitude error against the largest H vs cost";
  std::string script = fmt::format(
      "set title '{}'\nset logscale xy\nset format y '10^{{%L}}'\nset xlabel 'sweep time [s]'\n"
      "set ylabel '|relative amplitude error|'\nset grid\nset key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t i = 0; i < titles.size(); ++i)
    script += fmt::format(
        "{0}'{1}.dat' index {2} using 1:2 with linespoints pt 7 lc rgb '{3}' title '{4}', "
        "'{1}.dat' index {2} using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle",
        i ? ", \\\n     " : "", stem, i, series_colour(i), gnuplot_quote(titles[i]));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
