#include "report/model_comparison_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <stdexcept>

#include "report/gnuplot.hpp"
#include "report/html_page.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

std::string comparison_slug(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  return s;
}

// Every model's prediction of one quantity of a held-out set, over its measured points.
Plot plot_held_out(const std::vector<ModelScore>& scores, const std::vector<const CalibrationOutcome*>& outcomes,
                   const std::string& set, const std::string& quantity, const fs::path& out_dir) {
  const std::string stem = "held_out_" + comparison_slug(set) + "_" + quantity;
  double scale = 1.0;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (size_t m = 0; m < outcomes.size(); ++m) {
      out << "# " << scores[m].name << ": x measured sigma computed\n";
      for (const FitPoint& p : outcomes[m]->after)
        if (p.set == set && p.quantity == quantity) {
          scale = p.display_scale();
          out << p.x << ' ' << p.measured * scale << ' ' << p.sigma * scale << ' ' << p.computed * scale << '\n';
        }
      out << "\n\n";
    }
  }
  std::string shown = quantity;
  std::replace(shown.begin(), shown.end(), '_', ' ');
  const std::string title = fmt::format("{}: {} measured (held out) and predicted by each model", set, shown);
  std::string script = fmt::format(
      "set title '{}'\nset xlabel 'frequency [Hz]'\nset ylabel '{}{}'\nset grid\nset key outside right\n"
      "plot '{}.dat' index 0 using 1:2:3 with yerrorbars pt 7 ps 0.5 lc rgb 'black' title 'measured'",
      gnuplot_quote(title), shown, scale != 1.0 ? " [deg]" : " [SI]", stem);
  for (size_t m = 0; m < outcomes.size(); ++m)
    script += fmt::format(", \\\n     '{}.dat' index {} using 1:4 with lines lw 2 lc rgb '{}' title '{}'", stem, m,
                          series_colour(m), gnuplot_quote(scores[m].name));
  script += '\n';
  return draw(out_dir, stem, title, script);
}

}  // namespace

void write_model_comparison(const std::vector<ModelScore>& scores,
                            const std::vector<const CalibrationOutcome*>& outcomes, const fs::path& out_dir,
                            bool plots) {
  std::vector<size_t> order(scores.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return scores[a].rank < scores[b].rank; });
  {
    std::ofstream csv(out_dir / "ranking.csv");
    csv << "rank,model,converged,parameters,fitted_points,chi_square,aic,bic,held_out_points,held_out_rms_sigma,"
           "held_out_largest_error,band_coverage_95,cross_check_passed,cross_check_entries,leave_one_out_rms_sigma,"
           "folds,"
           "folds_converged\n";
    for (size_t i : order) {
      const ModelScore& s = scores[i];
      csv << fmt::format("{},\"{}\",{},{},{},{:.10g},{:.10g},{:.10g},{},{:.6g},{:.6g},{:.6g},{},{},{:.6g},{},{}\n",
                         s.rank, s.name, s.converged ? 1 : 0, s.parameters, s.fitted_points, s.chi_square, s.aic, s.bic,
                         s.held_out_points, s.held_out_rms, s.held_out_largest_error, s.band_coverage,
                         s.cross_check_passed, s.cross_check_entries, s.leave_one_out_rms, s.folds, s.folds_converged);
    }
    if (!csv) throw std::runtime_error("failed writing ranking.csv");
  }
  std::ofstream md(out_dir / "report.md");
  md << "# Model comparison\n\n"
        "Each model form calibrated on the same data (`bladebench calibrate`, its report in the folder named after "
        "it), ranked by the rms residual of the points held out of every fit (in sigma: what the model predicts), "
        "then by BIC. AIC = chi2 + 2 k and BIC = chi2 + k ln n, chi2 the sum of squared fitted residuals, k the "
        "parameters, n the fitted points: they reward the fit and charge the parameters, but only the held-out "
        "error measures prediction. With `--leave-one-out` each model is also refitted once per fitted curve with "
        "that curve held out, and ranked by the rms residual of every curve predicted by the fit that left it out "
        "(the leave-one-out column).\n\n"
        "| rank | model | converged | k | n | chi2 | AIC | BIC | held-out rms [sigma] | largest held-out error | "
        "95 % band covers | cross-check | leave-one-out rms [sigma] "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (size_t i : order) {
    const ModelScore& s = scores[i];
    // Each calibration's folder is named after its case file's stem (cli/compare_models_command.cpp).
    md << fmt::format(
        "| {} | [{}]({}/report.md) | {} | {} | {} | {:.4g} | {:.4g} | {:.4g} | {:.3g} | {:.3g} % | {} | "
        "{} of {} | {} |\n",
        s.rank, s.name, s.name, s.converged ? "yes" : "**no**", s.parameters, s.fitted_points, s.chi_square, s.aic,
        s.bic, s.held_out_rms, 100.0 * s.held_out_largest_error,
        s.band_coverage < 0.0 ? std::string("no band") : fmt::format("{:.1f} %", 100.0 * s.band_coverage),
        s.cross_check_passed, s.cross_check_entries,
        std::isnan(s.leave_one_out_rms)
            ? std::string("not run")
            : fmt::format("{:.3g} ({} of {} folds converged)", s.leave_one_out_rms, s.folds_converged, s.folds));
  }
  if (plots && !outcomes.empty()) {
    md << "\n## Predictions over the held-out curves\n\n";
    for (const CalibrationData& d : outcomes.front()->spec.data) {
      if (!d.held_out) continue;
      for (const char* quantity : {"force", "amplitude", "phase"}) {
        const bool any = std::any_of(outcomes.front()->after.begin(), outcomes.front()->after.end(),
                                     [&](const FitPoint& p) { return p.set == d.name && p.quantity == quantity; });
        if (!any) continue;
        const Plot p = plot_held_out(scores, outcomes, d.name, quantity, out_dir);
        md << (p.file.empty() ? fmt::format("- {}: not drawn ({})\n", p.title, p.note)
                              : fmt::format("![{}]({})\n\n", p.title, p.file));
      }
    }
  }
  md << "\nFiles: `ranking.csv`.\n";
  md.close();
  if (!md) throw std::runtime_error("failed writing the model comparison report");
  write_html_twin(out_dir / "report.md");
}

}  // namespace bb
