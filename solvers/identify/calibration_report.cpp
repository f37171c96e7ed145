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
  {
    std::ofstream out = open_out(out_dir / "calibrated.toml");
    out << fmt::format("# {} with the values identified by `bladebench calibrate` (comments are not kept).\n",
                       case_file.string());
    out << o.calibrated << '\n';
  }
  std::ofstream md = open_out(out_dir / "report.md");
  md << fmt::format("# Calibration of `{}`\n\n", case_file.string());
  md << fmt::format("{} in {:.1f} s, {} model evaluations. Cost {:.6g} -> {:.6g}; rms relative misfit {:.3f}% -> {:.3f}%.\n\n",
                    o.converged ? "Converged" : "**Not converged**", wall_seconds, o.residual_evaluations, o.initial_cost,
                    o.final_cost, 100 * rms_relative(o.before), 100 * rms_relative(o.after));
  md << "Residuals: (computed / reference - 1) / sigma per entry of the fitted checks. Loss: " << o.spec.loss << ".\n\n";
  md << "| fitted check | sigma (relative) |\n|---|---|\n";
  for (const std::string& name : o.spec.fit_checks) md << fmt::format("| {} | {:g} |\n", name, uncertainty_of(o.spec, name));
  md << '\n';
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
  md << fmt::format("\nSolver: {}\n\nFiles: `identification.csv`, `convergence.csv`, `calibrated.toml`.\n", o.termination);
  if (!md) throw std::runtime_error("failed writing the calibration report");
}

}  // namespace bb
