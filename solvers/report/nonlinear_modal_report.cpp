#include "report/nonlinear_modal_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/gnuplot.hpp"
#include "report/number_format.hpp"

namespace bb {

void describe(const NonlinearModalSpec& spec, const NonlinearModalOutcome& o, RunRecord& run) {
  const bool several = spec.modes.size() > 1;
  run.facts.emplace_back(
      "analysis",
      several ? fmt::format("{} uncoupled nonlinear modes summed at {}: m_k (w_k(a_k)^2 - w^2 + 2 i z_k(a_k) w_k(a_k) "
                            "w) x_k = F, a_k = |x_k|, x = sum x_k",
                            spec.modes.size(), spec.dof)
              : fmt::format("single-nonlinear-mode synthesis at {}: m (w0(a)^2 - w^2 + 2 i z(a) w0(a) w) x = F, "
                            "a = |x|, effective modal mass {} kg",
                            spec.dof, format_setting(spec.modes.front().mass)));
  for (size_t k = 0; k < spec.modes.size(); ++k) {
    const NonlinearMode& m = spec.modes[k];
    // Over both curves' knots: each may have its own.
    const auto& af = m.frequency_hz.amplitudes();
    const auto& az = m.damping_ratio.amplitudes();
    const double a_lo = std::min(af.front(), az.front()), a_hi = std::max(af.back(), az.back());
    const auto [f_lo, f_hi] = m.frequency_hz.range(a_lo, a_hi);
    const auto [z_lo, z_hi] = m.damping_ratio.range(a_lo, a_hi);
    run.facts.emplace_back(
        several ? fmt::format("backbone of mode {}", k) : std::string("backbone"),
        fmt::format("{}{} frequency and {} damping knots from {} to {} m (clamped cubic splines in log a, constant "
                    "beyond): f from {:.6g} to {:.6g} Hz ({:.3g} % apart), z from {:.4g} to {:.4g} ({:.3g}x)",
                    several ? fmt::format("mass {} kg, ", format_setting(m.mass)) : std::string(), af.size(), az.size(),
                    format_setting(a_lo), format_setting(a_hi), f_lo, f_hi, 100.0 * (f_hi - f_lo) / f_lo, z_lo, z_hi,
                    z_hi / z_lo));
  }
  run.facts.emplace_back("curves", fmt::format("{} force-controlled stepped sines, {} response-controlled",
                                               spec.stepped_sines.size(), spec.response_controls.size()));
  if (!spec.sensitivities.empty())
    run.facts.emplace_back("sensitivities", fmt::format("exact, to {} parameters", spec.sensitivities.size()));
  for (size_t k = 0; k < o.extracted.size(); ++k) {
    const BackbonePoint& p = o.extracted[k];
    run.facts.emplace_back(
        fmt::format("backbone point of {}", spec.extract[k].name),
        fmt::format("a = {:.4g} m: f0 = {:.6g} Hz, z = {:.4g}, m = {:.4g} kg (force balance, rms misfit {:.2g} %)",
                    p.amplitude_m, p.frequency_hz, p.damping_ratio, p.mass_kg, 100.0 * p.rms_relative));
  }
}

namespace {

// One mode's backbone (its table `stem`), with the points read from measured curves.
Plot plot_backbone(const NonlinearMode& mode, const NonlinearModalOutcome& o, const ResultTables& tables,
                   const std::filesystem::path& out, const std::string& stem, const std::string& title) {
  const ResultTable& b = tables.at(stem);
  {
    std::ofstream data = open_plot_data(out, stem);
    data << "# model: a [m] f [Hz] z\n";
    for (Eigen::Index r = 0; r < b.values.rows(); ++r)
      data << b.values(r, 1) << ' ' << b.values(r, 2) << ' ' << b.values(r, 3) << '\n';
    // Each curve's knots apart: they may lie at other amplitudes.
    for (const ModalBackbone* c : {&mode.frequency_hz, &mode.damping_ratio}) {
      data << "\n\n# knots: a [m] value\n";
      for (size_t k = 0; k < c->knots(); ++k) data << c->amplitudes()[k] << ' ' << c->values()[k] << '\n';
    }
    data << "\n\n# read from measured curves: a [m] f [Hz] z\n";
    for (const BackbonePoint& p : o.extracted)
      data << p.amplitude_m << ' ' << p.frequency_hz << ' ' << p.damping_ratio << '\n';
    if (o.extracted.empty()) data << "nan nan nan\n";
  }
  const std::string script = fmt::format(
      "set multiplot layout 2,1 title '{}'\nset logscale x\nset grid\nset key outside right\nset datafile missing "
      "'nan'\n"
      "set ylabel 'f_0 [Hz]'\nset format x ''\n"
      "plot '{s}.dat' index 0 using 1:2 with lines lw 1.5 lc rgb '{c0}' title 'model', \\\n"
      "     '{s}.dat' index 1 using 1:2 with points pt 6 lc rgb '{c0}' title 'knots', \\\n"
      "     '{s}.dat' index 3 using 1:2 with points pt 7 lc rgb '{c1}' title 'from the curves'\n"
      "set ylabel 'damping ratio z'\nset xlabel 'amplitude a [m]'\nset format x '%g'\n"
      "plot '{s}.dat' index 0 using 1:3 with lines lw 1.5 lc rgb '{c0}' title 'model', \\\n"
      "     '{s}.dat' index 2 using 1:2 with points pt 6 lc rgb '{c0}' title 'knots', \\\n"
      "     '{s}.dat' index 3 using 1:3 with points pt 7 lc rgb '{c1}' title 'from the curves'\n"
      "unset multiplot\n",
      gnuplot_quote(title), fmt::arg("s", stem), fmt::arg("c0", series_colour(0)), fmt::arg("c1", series_colour(1)));
  return draw(out, stem, title, script);
}

Plot plot_controlled(const NonlinearModalSpec& spec, const ResultTables& tables, const std::filesystem::path& out,
                     const std::string& stem) {
  {
    std::ofstream data = open_plot_data(out, stem);
    for (const ResponseControlSpec& c : spec.response_controls) {
      const ResultTable& t = tables.at("frf_" + c.name);
      data << "# " << c.name << ": f [Hz] F [N]\n";
      for (Eigen::Index r = 0; r < t.values.rows(); ++r) data << t.values(r, 1) << ' ' << t.values(r, 2) << '\n';
      data << "\n\n";
    }
  }
  const std::string title = "Response-controlled curves: the force that holds each level";
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'frequency [Hz]'\nset ylabel 'force amplitude [N]'\nset logscale y\nset grid\n"
      "set key outside right\nplot ",
      gnuplot_quote(title));
  for (size_t k = 0; k < spec.response_controls.size(); ++k)
    script +=
        fmt::format("{}'{}.dat' index {} using 1:2 with lines lw 1.5 lc rgb '{}' title '{}'", k ? ", \\\n     " : "",
                    stem, k, series_colour(k), gnuplot_quote(spec.response_controls[k].name));
  script += '\n';
  return draw(out, stem, title, script);
}

}  // namespace

void plot_nonlinear_modal(const NonlinearModalSpec& spec, const NonlinearModalOutcome& o, const ResultTables& tables,
                          const std::filesystem::path& out, RunRecord& run) {
  const std::string title = "Backbone: natural frequency and damping ratio against the amplitude";
  if (spec.modes.size() == 1)
    run.plots.push_back(plot_backbone(spec.modes.front(), o, tables, out, "backbone", title));
  else
    for (size_t k = 0; k < spec.modes.size(); ++k)
      run.plots.push_back(plot_backbone(spec.modes[k], o, tables, out, fmt::format("backbone_{}", k),
                                        fmt::format("Mode {}: {}", k, title)));
  if (!spec.response_controls.empty()) run.plots.push_back(plot_controlled(spec, tables, out, "response_control"));
}

}  // namespace bb
