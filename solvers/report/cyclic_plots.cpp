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
