#include "identify/calibration_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "report/plots.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

std::ofstream open_out(const fs::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  return out;
}

double rms_relative(const std::vector<CheckEntry>& entries) {
  double sum = 0.0;
  for (const CheckEntry& e : entries) sum += std::pow(e.computed / e.reference - 1.0, 2);
  return entries.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(entries.size()));
}

}  // namespace

void write_calibration_outputs(const CalibrationOutcome& o, const fs::path& case_file, double wall_seconds,
                               const fs::path& out_dir) {
  fs::create_directories(out_dir);
  fs::remove(out_dir / "report.md");
  {
    std::ofstream out = open_out(out_dir / "identification.csv");
    out << "parameter,start,value,std,lower,upper\n";
    for (size_t i = 0; i < o.values.size(); ++i) {
      const auto& p = o.spec.parameters[i];
      out << fmt::format("{},{:.10g},{:.10g},{:.6g},{:.10g},{:.10g}\n", p.path, p.start, o.values[i], o.std_devs[i], p.lower, p.upper);
    }
  }
  {
    std::ofstream out = open_out(out_dir / "convergence.csv");
    out << "iteration,cost\n";
    for (const auto& [it, cost] : o.history) out << fmt::format("{},{:.10g}\n", it, cost);
  }
  fs::remove(out_dir / "calibrated.toml");  // a failed fit must not leave an earlier one looking current
  if (o.converged) {
    std::ofstream out = open_out(out_dir / "calibrated.toml");
    out << fmt::format("# {} with the values identified by `bladebench calibrate` (comments are not kept).\n",
                       case_file.string());
    out << o.calibrated << '\n';
  }
  {
    std::ofstream out = open_out(out_dir / "starts.csv");
    out << "start,converged,initial_cost,final_cost,iterations";
    for (const auto& p : o.spec.parameters) out << ",start_" << p.path << ",value_" << p.path;
    out << '\n';
    for (size_t s = 0; s < o.starts.size(); ++s) {
      const CalibrationStart& r = o.starts[s];
      out << fmt::format("{},{},{:.10g},{:.10g},{}", s + 1, r.converged ? 1 : 0, r.initial_cost, r.final_cost, r.iterations);
      for (size_t i = 0; i < r.values.size(); ++i) out << fmt::format(",{:.10g},{:.10g}", r.start[i], r.values[i]);
      out << '\n';
    }
  }
  std::ofstream md = open_out(out_dir / "report.md");
  md << fmt::format("# Calibration of `{}`\n\n", case_file.string());
  md << fmt::format("{} in {:.1f} s, {} model evaluations. Cost {:.6g} -> {:.6g}; rms relative misfit {:.3f}% -> {:.3f}%.\n\n",
                    o.converged ? "Converged" : "**Not converged**", wall_seconds, o.residual_evaluations, o.initial_cost,
                    o.final_cost, 100 * rms_relative(o.before), 100 * rms_relative(o.after));
  md << "Residuals: (computed / reference - 1) / sigma per entry of the fitted checks. Loss: " << o.spec.loss << ".\n\n";
  md << fmt::format("Reduced chi-square at the optimum: {:.3g}{}.\n\n", o.reduced_chi_square,
                    o.reduced_chi_square > 1 ? " (above 1: the standard deviations below are scaled up by its square root)" : "");
  md << "| fitted check | sigma (relative) |\n|---|---|\n";
  for (const std::string& name : o.spec.fit_checks) md << fmt::format("| {} | {:g} |\n", name, uncertainty_of(o.spec, name));
  md << '\n';
  if (o.starts.size() > 1) {
    md << fmt::format("## Starts\n\n{} starts (the case's values, then a Latin hypercube in log space, seed {}); start {} is reported.\n\n",
                      o.starts.size(), o.spec.seed, o.best + 1);
    md << "| start | converged | cost at start | final cost | iterations |\n|---|---|---|---|---|\n";
    for (size_t s = 0; s < o.starts.size(); ++s)
      md << fmt::format("| {} | {} | {:.6g} | {:.6g} | {} |\n", s + 1, o.starts[s].converged ? "yes" : "no", o.starts[s].initial_cost,
                        o.starts[s].final_cost, o.starts[s].iterations);
    md << "\nValues at every start and end: `starts.csv`.\n\n";
  }
  md << "## Parameters\n\n| parameter | start | identified | std (1 sigma) | lower | upper |\n|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < o.values.size(); ++i) {
    const auto& p = o.spec.parameters[i];
    md << fmt::format("| `{}` | {:.6g} | {:.6g} | {:.3g} | {:.6g} | {:.6g} |\n", p.path, p.start, o.values[i], o.std_devs[i],
                      p.lower, p.upper);
  }
  if (o.correlation.size() > 0) {
    md << "\nCorrelation matrix:\n\n|   |";
    for (size_t j = 0; j < o.values.size(); ++j) md << fmt::format(" {} |", j + 1);
    md << "\n|---|";
    for (size_t j = 0; j < o.values.size(); ++j) md << "---|";
    md << '\n';
    for (Eigen::Index i = 0; i < o.correlation.rows(); ++i) {
      md << fmt::format("| {} |", i + 1);
      for (Eigen::Index j = 0; j < o.correlation.cols(); ++j) md << fmt::format(" {:+.3f} |", o.correlation(i, j));
      md << '\n';
    }
  }
  if (!o.warnings.empty()) {
    md << "\n## Warnings\n\n";
    for (const auto& w : o.warnings) md << "- " << w << '\n';
  }
  md << "\n## Fitted entries\n\n| entry | reference | start value | error | identified value | error |\n|---|---|---|---|---|---|\n";
  for (size_t k = 0; k < o.after.size() && k < o.before.size(); ++k) {
    const CheckEntry& b = o.before[k];
    const CheckEntry& a = o.after[k];
    md << fmt::format("| {} | {:.6g} | {:.6g} | {:+.3f}% | {:.6g} | {:+.3f}% |\n", a.name, a.reference, b.computed,
                      100 * (b.computed / b.reference - 1), a.computed, 100 * (a.computed / a.reference - 1));
  }
  md << fmt::format("\nSolver: {}\n\nFiles: `identification.csv`, `convergence.csv`, `starts.csv`{}.\n", o.termination,
                    o.converged ? ", `calibrated.toml`" : " (no `calibrated.toml`: the fit did not converge)");
  if (!md) throw std::runtime_error("failed writing the calibration report");
}

}  // namespace bb
