#include "report/cyclic_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

#include "report/gnuplot.hpp"
#include "report/plots.hpp"

namespace bb {

namespace fs = std::filesystem;

Plot plot_nodal_diameter_map(const CyclicModalOutcome& o, const CyclicModalSpec& spec, const fs::path& out_dir,
                             const std::string& stem) {
  const Eigen::Index families = common_families(o.diameters);
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (Eigen::Index f = 0; f < families; ++f) {
      out << "# family " << f + 1 << ": nodal_diameter frequency_hz\n";
      for (const NodalDiameterModes& nd : o.diameters) out << nd.nodal_diameter << ' ' << nd.frequencies_hz[f] << '\n';
      out << "\n\n";
    }
    // Each engine order's excitation at the top speed, at the nodal diameter it excites.
    out << "# engine orders at the top speed: nodal_diameter frequency_hz engine_order\n";
    for (int eo : spec.engine_orders)
      out << excited_nodal_diameter(eo, spec.sectors) << ' ' << eo * spec.max_speed_rpm / 60.0 << ' ' << eo << '\n';
    if (spec.engine_orders.empty()) out << "nan nan nan\n";
  }
  const std::string title = fmt::format("Nodal-diameter map of the {}-sector structure{}", spec.sectors,
                                        spec.engine_orders.empty() ? "" : ", engine orders at the top speed");
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'nodal diameter'\nset ylabel 'frequency [Hz]'\nset grid\nset key outside right\n"
      "set xrange [-0.5:{}]\nset xtics 1\nset datafile missing 'nan'\nplot ",
      gnuplot_quote(title), spec.sectors / 2 + 0.5);
  for (Eigen::Index f = 0; f < families; ++f)
    script += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints pt 7 ps 0.6 title 'family {}'",
                          f ? ", \\\n     " : "", stem, f, f + 1);
  if (!spec.engine_orders.empty())
    script += fmt::format(
        ", \\\n     '{}.dat' index {} using 1:2 with points pt 6 ps 1.4 lc rgb 'black' title 'EO x {:g} rpm / 60', \\\n"
        "     '' index {} using 1:2:(sprintf('EO %d', $3)) with labels offset 1.5,0.6 notitle",
        stem, families, spec.max_speed_rpm, families);
  return draw(out_dir, stem, title, script + "\n");
}

Plot plot_cyclic_campbell(const CyclicModalOutcome& o, const CyclicModalSpec& spec, const fs::path& out_dir,
                          const std::string& stem) {
  // The diagram holds the nodal diameters the engine orders excite (all without engine orders).
  const CyclicCampbell& c = *o.campbell;
  const double rpm_per_rad_s = 60.0 / (2 * std::numbers::pi);
  int blocks = 0;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t d = 0; d < c.nodal_diameters.size(); ++d)
      for (Eigen::Index f = 0; f < c.frequencies_hz[d].cols(); ++f, ++blocks) {
        out << "# ND " << c.nodal_diameters[d] << " family " << f + 1 << ": speed_rpm frequency_hz\n";
        for (size_t s = 0; s < c.speeds.size(); ++s)
          out << c.speeds[s] * rpm_per_rad_s << ' ' << c.frequencies_hz[d](static_cast<Eigen::Index>(s), f) << '\n';
        out << "\n\n";
      }
    out << "# crossings: speed_rpm frequency_hz engine_order\n";
    for (const CyclicCrossing& x : o.crossings)
      out << x.speed * rpm_per_rad_s << ' ' << x.frequency_hz << ' ' << x.engine_order << '\n';
    if (o.crossings.empty()) out << "nan nan nan\n";
  }
  const double top = c.speeds.back() * rpm_per_rad_s;
  double f_top = 0.0;
  for (const Eigen::MatrixXd& f : c.frequencies_hz)
    f_top = std::max(f_top, f.col(std::min<Eigen::Index>(2, f.cols() - 1)).maxCoeff());
  const std::string title =
      "Campbell diagram by nodal diameter (the ones the engine orders excite) and engine-order lines";
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'speed [rpm]'\nset ylabel 'frequency [Hz]'\nset grid\nset key outside right\n"
      "set xrange [0:{:.12g}]\nset yrange [0:{:.12g}]\nset datafile missing 'nan'\nplot ",
      gnuplot_quote(title), top, 1.15 * f_top);
  // One colour per nodal diameter, named once: its families are the lines of that colour.
  int b = 0;
  for (size_t d = 0; d < c.nodal_diameters.size(); ++d)
    for (Eigen::Index f = 0; f < c.frequencies_hz[d].cols(); ++f, ++b)
      script +=
          fmt::format("{}'{}.dat' index {} using 1:2 with linespoints pt 7 ps 0.4 lc {} {}", b ? ", \\\n     " : "",
                      stem, b, d + 1, f == 0 ? fmt::format("title 'ND {}'", c.nodal_diameters[d]) : "notitle");
  script += fmt::format(
      ", \\\n     '{}.dat' index {} using 1:2 with points pt 6 ps 1.2 lc rgb 'black' title 'crossings'", stem, blocks);
  for (int eo : spec.engine_orders)
    script += fmt::format(", \\\n     x * {} / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO {}'", eo, eo);
  return draw(out_dir, stem, title, script + "\n");
}

Plot plot_sector_wave(const CyclicModalOutcome& o, const Mesh& mesh, size_t index, int family, const fs::path& out_dir,
                      const std::string& stem) {
  const NodalDiameterModes& nd = o.diameters.at(index);
  return plot_deformed_mesh(mesh, nodal_rows(o.dofs, nd.cosine.col(family - 1)), out_dir, stem,
                            fmt::format("Nodal diameter {}, family {}: {:.2f} Hz (cosine part on the sector)",
                                        nd.nodal_diameter, family, nd.frequencies_hz[family - 1]));
}

}  // namespace bb
