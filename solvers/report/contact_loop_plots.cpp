#include "report/contact_loop_plots.hpp"

#include <fmt/format.h>

#include <array>

#include "report/gnuplot.hpp"

namespace bb {

Plot plot_contact_loop(const ContactLoopOutcome& loop, const std::filesystem::path& out_dir, const std::string& stem) {
  const friction::AftResult& a = loop.aft;
  using friction::ContactState;
  const std::array<ContactState, 4> states{ContactState::stick, ContactState::slip_positive,
                                           ContactState::slip_negative, ContactState::lift_off};
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# the closed loop: u [m] T [N]\n";
    for (Eigen::Index k = 0; k <= a.u.size(); ++k) out << a.u[k % a.u.size()] << ' ' << a.t[k % a.u.size()] << '\n';
    for (ContactState s : states) {
      // One block per state; "nan nan" keeps the block (and the indices) when a state never occurs.
      out << "\n\n# samples in state " << friction::state_name(s) << ": u [m] T [N]\n";
      bool any = false;
      for (Eigen::Index k = 0; k < a.u.size(); ++k)
        if (a.state[static_cast<size_t>(k)] == s) out << a.u[k] << ' ' << a.t[k] << '\n', any = true;
      if (!any) out << "nan nan\n";
    }
  }
  const std::string title = fmt::format("Hysteresis loop: energy {:.4g} J per cycle, max |T| {:.4g} N",
                                        loop.summary.dissipated_energy, loop.summary.max_tangential_force);
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'relative tangential displacement u [m]'\nset ylabel 'tangential force T [N]'\n"
      "set grid\nset key outside right\nset datafile missing 'nan'\n"
      "plot '{}.dat' index 0 using 1:2 with lines lw 1.5 lc rgb '#7f7f7f' title 'loop'",
      gnuplot_quote(title), stem);
  for (size_t i = 0; i < states.size(); ++i)
    script += fmt::format(", \\\n     '{}.dat' index {} using 1:2 with points pt 7 ps 0.5 lc rgb '{}' title '{}'", stem,
                          i + 1, series_colour(i), friction::state_name(states[i]));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
