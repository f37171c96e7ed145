// The Jacobian of a calibration (identify/calibrate_case.hpp): the FRF round trip of the 1-DOF
// friction oscillator (tests/unit/hbm_frf_sensitivity_test.cpp: kt, mu, zeta; two levels, 0.3 N
// stick-slip and 10 N gross slip, 150-240 Hz at 0.5 Hz, 128 AFT samples; 31 measured frequencies
// per level with amplitude and phase, 124 residuals). Units: SI.
//   BM_CalibrationJacobianAnalytic           one run of the case with `sensitivities`, the
//                                            Jacobian interpolated from the dlog columns
//   BM_CalibrationJacobianCentralDifference  2 n = 6 runs of the case, the residuals differenced
//                                            with the calibration's step (derivative_step = 1e-2)
// Their time ratio is what [calibration] derivatives = "auto" saves per Jacobian.
// Measurement only: nothing here asserts a time. Counter max_difference: the largest
// |J_analytic - J_central| over all entries, in units of the largest |J| entry.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "cases/parse_calibration.hpp"
#include "identify/fit_points.hpp"
#include "identify/synthetic_data.hpp"
#include "model/build_model.hpp"

namespace {

namespace fs = std::filesystem;

const char* kCase = R"([case]
name = "frf_jacobian"
[analysis]
type = "hbm"
frequency_hz = [150.0, 240.0]
step_hz = 0.5
harmonics = 1
time_samples = 128
modal_damping = 0.01
forces = [{ dof = "A.x", amplitude = 1.0 }]
force_levels = [0.3, 10.0]
responses = ["A.x"]
[analysis.model]
name = "oscillator"
dofs = ["A.x"]
stiffness = [[1.0e6]]
mass = [[1.0]]
[[analysis.contact]]
name = "ground"
tangential = { "A.x" = 1.0 }
kn = 1.0e6
kt = 1.5e6
mu = 0.35
n0 = 30.0
[calibration]
parameters = [{ path = "analysis.contact.0.kt", lower = 1.0e5, upper = 1.0e7 },
              { path = "analysis.contact.0.mu", lower = 0.05, upper = 2.0 },
              { path = "analysis.modal_damping", lower = 0.001, upper = 0.1 }]
)";

struct Problem {
  fs::path file;
  toml::table base;
  bb::CalibrationSpec cal;
  std::vector<std::string> paths;
};

// The case and its synthetic data (2 % noise) in a temporary folder.
const Problem& problem() {
  static const Problem p = [] {
    Problem out;
    const fs::path dir = fs::temp_directory_path() / ("bladebench_bench_calibration_" + std::to_string(getpid()));
    fs::create_directories(dir);
    out.file = dir / "case.toml";
    std::string text = kCase;
    {
      const bb::CaseSpec spec = bb::parse_case_table(toml::parse(text), out.file);
      const bb::AnalysisResults r = bb::run_analysis(spec.analysis, bb::build_model(spec.model));
      bb::SyntheticOptions o;
      o.kind = bb::DataKind::frf;
      o.noise = 0.02;
      o.phase_noise = 0.02;
      o.every = 6;
      o.columns = {
          {"frequency", "frequency_hz", "Hz"}, {"amplitude", "A.x_amp_m", "um"}, {"phase", "A.x_phase_deg", "deg"}};
      for (const std::string level : {"0.3", "10"}) {
        bb::write_synthetic_data(r.tables.at("frf_" + level), o, dir / ("frf_" + level + ".csv"));
        text +=
            "[[calibration.data]]\nkind = \"frf\"\nfile = \"frf_" + level + ".csv\"\ntable = \"frf_" + level +
            "\"\ncolumns = { frequency = \"frequency_hz\", amplitude = \"A.x_amp_m\", phase = \"A.x_phase_deg\" }\n";
      }
    }
    std::ofstream(out.file) << text;
    out.base = bb::read_case_table(out.file);
    out.cal = *bb::parse_calibration(out.base, out.file, bb::parse_case_table(out.base, out.file));
    for (const bb::CalibrationParameter& c : out.cal.parameters) out.paths.push_back(c.path);
    fs::remove_all(dir);  // the data are read; the case runs need no file
    return out;
  }();
  return p;
}

std::vector<bb::FitPoint> points(const toml::table& t, const Problem& p, bool gradients) {
  const bb::CaseSpec spec = bb::parse_case_table(t, p.file);
  const bb::AnalysisResults r = bb::run_analysis(spec.analysis, bb::build_model(spec.model));
  std::vector<bb::FitPoint> out;
  for (const bb::CalibrationData& d : p.cal.data) {
    const auto e = bb::data_points(d, r.tables, gradients ? p.paths : std::vector<std::string>{});
    out.insert(out.end(), e.begin(), e.end());
  }
  return out;
}

// Residual rows x parameters, d r / d log p.
Eigen::MatrixXd analytic_jacobian(const Problem& p) {
  toml::table t = p.base;
  toml::array list;
  for (const std::string& s : p.paths) list.push_back(s);
  t["analysis"].as_table()->insert_or_assign("sensitivities", std::move(list));
  const std::vector<bb::FitPoint> pts = points(t, p, true);
  Eigen::MatrixXd j(static_cast<Eigen::Index>(pts.size()), static_cast<Eigen::Index>(p.paths.size()));
  for (size_t k = 0; k < pts.size(); ++k)
    for (size_t i = 0; i < p.paths.size(); ++i)
      j(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)) = pts[k].gradient.at(i);
  return j;
}

Eigen::MatrixXd central_jacobian(const Problem& p) {
  const double h = p.cal.derivative_step;
  Eigen::MatrixXd j;
  for (size_t i = 0; i < p.paths.size(); ++i) {
    std::vector<bb::FitPoint> side[2];
    for (int s = 0; s < 2; ++s) {
      toml::table t = p.base;
      toml::node* n = bb::node_at_path(t, p.paths[i]);
      *n->as_floating_point() = n->value<double>().value() * std::exp(s == 0 ? h : -h);
      side[s] = points(t, p, false);
    }
    if (j.size() == 0) j.resize(static_cast<Eigen::Index>(side[0].size()), static_cast<Eigen::Index>(p.paths.size()));
    for (size_t k = 0; k < side[0].size(); ++k)
      j(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)) =
          (side[0][k].residual() - side[1][k].residual()) / (2 * h);
  }
  return j;
}

void BM_CalibrationJacobianAnalytic(benchmark::State& state) {
  const Problem& p = problem();
  Eigen::MatrixXd j;
  for (auto _ : state) j = analytic_jacobian(p);
  const Eigen::MatrixXd c = central_jacobian(p);
  state.counters["residuals"] = static_cast<double>(j.rows());
  state.counters["case_runs"] = 1;
  state.counters["max_difference"] = (j - c).cwiseAbs().maxCoeff() / c.cwiseAbs().maxCoeff();
}
BENCHMARK(BM_CalibrationJacobianAnalytic)->Unit(benchmark::kMillisecond);

void BM_CalibrationJacobianCentralDifference(benchmark::State& state) {
  const Problem& p = problem();
  Eigen::MatrixXd j;
  for (auto _ : state) j = central_jacobian(p);
  state.counters["residuals"] = static_cast<double>(j.rows());
  state.counters["case_runs"] = static_cast<double>(2 * p.paths.size());
}
BENCHMARK(BM_CalibrationJacobianCentralDifference)->Unit(benchmark::kMillisecond);

}  // namespace
