#include "report/fidelity_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/gnuplot.hpp"

namespace bb {

Plot plot_fidelity_frontier(const ResultTable& frontier, const FidelitySpec& fidelity,
                            const std::filesystem::path& out_dir, const std::string& stem) {
  const auto col = [&](const char* name) { return *frontier.column_index(name); };
  const std::vector<std::string>& axis_of_row = frontier.text.at(0);
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# seconds estimated_error run: the combinations climbed (block 0), the chosen one (block 1)\n";
    for (int block = 0; block < 2; ++block) {
      for (Eigen::Index r = 0; r < frontier.values.rows(); ++r) {
        const double e = frontier.values(r, col("estimated_error"));
        if (axis_of_row[static_cast<size_t>(r)] != "combined" || !std::isfinite(e)) continue;
        if (block == 1 && frontier.values(r, col("chosen")) != 1.0) continue;
        out << frontier.values(r, col("seconds")) << ' ' << std::max(e, 1e-16) << ' ' << frontier.values(r, col("run"))
            << '\n';
      }
      out << "0 nan 0\n\n\n";  // keeps both blocks non-empty
    }
  }
  const std::string title = fmt::format(
      "Fidelity: estimated error of '{}' against the cost of each combination climbed (labels: run; target {:.3g})",
      fidelity.result, fidelity.target);
  const std::string script = fmt::format(
      "set title '{0}'\nset logscale xy\nset format y '10^{{%L}}'\nset xlabel 'wall time of the run [s]'\n"
      "set ylabel 'estimated relative error'\nset grid\nset key outside right\nset datafile missing 'nan'\n"
      "plot '{1}.dat' index 0 using 1:2 with linespoints pt 7 title 'combination', '{1}.dat' index 0 using "
      "1:2:(sprintf('%d', $3)) with labels offset 0,1 notitle, \\\n     '{1}.dat' index 1 using 1:2 with points pt 6 "
      "ps 3 lc rgb '#d62728' title 'chosen', \\\n     {2} with lines dt 2 lc rgb '#7f7f7f' title 'target'\n",
      gnuplot_quote(title), stem, fidelity.target);
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
