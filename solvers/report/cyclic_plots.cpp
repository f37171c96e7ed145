#include "report/cyclic_plots.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/gnuplot.hpp"
#include "report/plots.hpp"

namespace bb {

namespace fs = std::filesystem;

Plot plot_nodal_diameter_map(const CyclicModalOutcome& o, const CyclicModalSpec& spec, const fs::path& out_dir,
                             const std::string& stem) {
  Eigen::Index families = o.diameters.empty() ? 0 : o.diameters.front().frequencies_hz.size();
  for (const NodalDiameterModes& nd : o.diameters) families = std::min(families, nd.frequencies_hz.size());
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (Eigen::Index f = 0; f < families; ++f) {
      out << "# family " << f + 1 << ": nodal_diameter frequency_hz\n";
      for (const NodalDiameterModes& nd : o.diameters) out << nd.nodal_diameter << ' ' << nd.frequencies_hz[f] << '\n';
      out << "\n\n";
    }
    // Each engine order's excitation at the top speed, at the nodal diameter it excites.
    out << "# engine orders at the top speed: nodal_diameter frequency_hz engine_order\n";
    for (int eo : spec.engine_orders) {
      const int k = eo % spec.sectors;
      out << std::min(k, spec.sectors - k) << ' ' << eo * spec.max_speed_rpm / 60.0 << ' ' << eo << '\n';
    }
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
  const CyclicCampbell& c = *o.campbell;
  std::vector<size_t> shown;
  for (size_t d = 0; d < c.nodal_diameters.size(); ++d) {
    bool excited = spec.engine_orders.empty();
    for (int eo : spec.engine_orders)
      excited = excited || excited_nodal_diameter(eo, spec.sectors) == c.nodal_diameters[d];
    if (excited) shown.push_back(d);
  }
  const double rpm_per_rad_s = 60.0 / (2 * 3.141592653589793);
  int blocks = 0;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t d : shown)
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
  for (size_t d : shown)
    f_top =
        std::max(f_top, c.frequencies_hz[d].col(std::min<Eigen::Index>(2, c.frequencies_hz[d].cols() - 1)).maxCoeff());
  const std::string title =
      "Campbell diagram by nodal diameter (the ones the engine orders excite) and engine-order lines";
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'speed [rpm]'\nset ylabel 'frequency [Hz]'\nset grid\nset key outside right\n"
      "set xrange [0:{:.12g}]\nset yrange [0:{:.12g}]\nset datafile missing 'nan'\nplot ",
      gnuplot_quote(title), top, 1.15 * f_top);
  // One colour per nodal diameter, named once: its families are the lines of that colour.
  int b = 0;
  for (size_t i = 0; i < shown.size(); ++i)
    for (Eigen::Index f = 0; f < c.frequencies_hz[shown[i]].cols(); ++f, ++b)
      script +=
          fmt::format("{}'{}.dat' index {} using 1:2 with linespoints pt 7 ps 0.4 lc {} {}", b ? ", \\\n     " : "",
                      stem, b, i + 1, f == 0 ? fmt::format("title 'ND {}'", c.nodal_diameters[shown[i]]) : "notitle");
  script += fmt::format(
      ", \\\n     '{}.dat' index {} using 1:2 with points pt 6 ps 1.2 lc rgb 'black' title 'crossings'", stem, blocks);
  for (int eo : spec.engine_orders)
    script += fmt::format(", \\\n     x * {} / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO {}'", eo, eo);
  return draw(out_dir, stem, title, script + "\n");
}

Plot plot_sector_wave(const CyclicModalOutcome& o, const Mesh& mesh, size_t index, int family, const fs::path& out_dir,
                      const std::string& stem) {
  const NodalDiameterModes& nd = o.diameters.at(index);
  const Eigen::VectorXd global = to_global(o.dofs, nd.cosine.col(family - 1), false);
  Eigen::MatrixXd u(mesh.n_nodes(), mesh.dim);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    for (int d = 0; d < mesh.dim; ++d) u(n, d) = global[n * mesh.dim + d];
  return plot_deformed_mesh(mesh, u, out_dir, stem,
                            fmt::format("Nodal diameter {}, family {}: {:.2f} Hz (cosine part on the sector)",
                                        nd.nodal_diameter, family, nd.frequencies_hz[family - 1]));
}

}  // namespace bb
