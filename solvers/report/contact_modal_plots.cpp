#include "report/contact_modal_plots.hpp"

#include <fmt/format.h>

#include "report/gnuplot.hpp"

namespace bb {

namespace fs = std::filesystem;

Plot plot_contact_mode(const ContactModalOutcome& o, const ContactModalSpec& spec, int mode, const fs::path& out_dir,
                       const std::string& stem) {
  const size_t n_p = spec.penalty_factors.size();
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t i = 0; i < spec.interferences.size(); ++i) {
      out << "# interference " << spec.interferences[i] << " m: fkn frequency_hz\n";
      for (size_t j = 0; j < n_p; ++j)
        out << spec.penalty_factors[j] << ' ' << o.grid[i * n_p + j].frequencies_hz[mode - 1] << '\n';
      out << "\n\n";
    }
  }
  const std::string title = fmt::format("Mode {}: frequency against the normal penalty factor FKN", mode);
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'FKN (kn = FKN E / h)'\nset ylabel 'frequency [Hz]'\nset logscale x\nset grid\n"
      "set key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t i = 0; i < spec.interferences.size(); ++i)
    script += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints pt 7 ps 0.5 title 'interference {:g} m'",
                          i ? ", \\\n     " : "", stem, i, spec.interferences[i]);
  if (o.glued_hz.size() >= mode)
    script += fmt::format(", \\\n     {:.12g} with lines dt 2 lc rgb 'black' title 'glued'", o.glued_hz[mode - 1]);
  script += '\n';
  return draw(out_dir, stem, title, script);
}

Plot plot_contact_pressure(const ContactModalOutcome& o, const ResultTable& s, const fs::path& out_dir,
                           const std::string& stem) {
  const int pair = *s.column_index("pair"), x = *s.column_index("x_m"), p = *s.column_index("pressure_pa");
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t k = 0; k < o.pair_names.size(); ++k) {
      out << "# pair " << o.pair_names[k] << ": x_m pressure_pa\n";
      bool any = false;
      for (Eigen::Index r = 0; r < s.values.rows(); ++r)
        if (static_cast<size_t>(s.values(r, pair)) == k + 1) {
          out << s.values(r, x) << ' ' << s.values(r, p) << '\n';
          any = true;
        }
      if (!any) out << "nan nan\n";
      out << "\n\n";
    }
  }
  const std::string title = "Contact pressure at the Gauss points of every pair (state point)";
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'x [m]'\nset ylabel 'pressure [Pa]'\nset grid\nset key outside right\n"
      "set datafile missing 'nan'\nplot ",
      gnuplot_quote(title));
  for (size_t k = 0; k < o.pair_names.size(); ++k)
    script += fmt::format("{}'{}.dat' index {} using 1:2 with points pt 7 ps 0.4 title '{}'", k ? ", \\\n     " : "",
                          stem, k, gnuplot_quote(o.pair_names[k]));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
