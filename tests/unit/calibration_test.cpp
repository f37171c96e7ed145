// Calibration (identify/calibrate_case): round trips on a small modal case whose reference
// frequencies are computed by the solver itself at known parameter values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "cases/parse_calibration.hpp"
#include "model/build_model.hpp"
#include "pipeline/calibrate_case.hpp"
#include "report/calibration_report.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

const char* kCase = R"(
[case]
name = "calibration_round_trip"
[material]
E = {E}
nu = 0.3
rho = {rho}
[section]
thickness = 0.1
[mesh]
kind = "mapped_quad"
element = "q4"
corners = [[0.0, 0.0], [2.0, 0.0], [2.0, 0.2], [0.0, 0.2]]
nx = 20
ny = 2
[sets.clamp]
x = 0.0
[[bc]]
set = "clamp"
dofs = ["x", "y"]
[analysis]
type = "modal"
modes = 3
[[check]]
name = "frequencies"
result = "frequencies"
reference = "reference.csv"
key = "mode"
compare = { frequency_hz = "frequency_hz" }
rel_tol = 0.01
[calibration]
parameters = [{parameters}]
fit_checks = ["frequencies"]
relative_uncertainty = 0.001
)";

std::string substitute(std::string text, const std::string& key, const std::string& value) {
  const std::string token = "{" + key + "}";
  text.replace(text.find(token), token.size(), value);
  return text;
}

class CalibrationRoundTrip : public test::TempFolderTest {
 protected:
  // Writes the case with the given values and, from the truth values, its reference file.
  fs::path write_case(double e_start, double rho_start, const std::string& parameters, double e_true, double rho_true) {
    write_values(dir_ / "truth.toml", e_true, rho_true, parameters);
    std::ofstream(dir_ / "reference.csv") << "mode,frequency_hz\n1,1\n2,1\n3,1\n";  // placeholder for parsing
    const CaseSpec truth = parse_case_file(dir_ / "truth.toml");
    const AnalysisResults r = run_analysis(truth.analysis, build_model(truth.model));
    std::ofstream ref(dir_ / "reference.csv");
    ref.precision(17);
    ref << "mode,frequency_hz\n";
    for (Eigen::Index i = 0; i < std::get<ModalOutcome>(r.outcome).modal.frequencies_hz.size(); ++i)
      ref << i + 1 << ',' << std::get<ModalOutcome>(r.outcome).modal.frequencies_hz[i] << '\n';
    ref.close();
    write_values(dir_ / "case.toml", e_start, rho_start, parameters);
    return dir_ / "case.toml";
  }
  // E fitted from e_start towards 2.1e11 with one iteration allowed: a fit that does not converge.
  fs::path one_iteration_case(double e_start) {
    const fs::path c =
        write_case(e_start, 7800.0, R"({ path = "material.E", lower = 1e11, upper = 3e11 })", 2.1e11, 7800.0);
    std::ofstream(c, std::ios::app) << "max_iterations = 1\n";
    return c;
  }

 private:
  static void write_values(const fs::path& file, double e, double rho, const std::string& parameters) {
    std::string text =
        substitute(substitute(substitute(std::string(kCase), "E", std::to_string(e)), "rho", std::to_string(rho)),
                   "parameters", parameters);
    std::ofstream(file) << text;
  }
};

TEST_F(CalibrationRoundTrip, RecoversYoungsModulusFromFrequencies) {
  const fs::path c =
      write_case(1.5e11, 7800.0, R"({ path = "material.E", lower = 1e11, upper = 3e11 })", 2.1e11, 7800.0);
  const CalibrationOutcome o = calibrate_case(c);
  ASSERT_TRUE(o.converged) << o.termination;
  EXPECT_NEAR(o.values[0] / 2.1e11, 1.0, 1e-6);
  EXPECT_LT(o.final_cost, 1e-8 * o.initial_cost);
  for (const FitPoint& e : o.after) EXPECT_NEAR(e.computed / e.measured, 1.0, 1e-7) << e.label;
  EXPECT_TRUE(std::isfinite(o.std_devs[0]));
}

TEST_F(CalibrationRoundTrip, StiffnessAndDensityTogetherAreFlaggedAsNotIdentifiable) {
  // Frequencies scale with sqrt(E / rho): only the ratio is identifiable.
  const fs::path c = write_case(
      1.8e11, 7000.0,
      R"({ path = "material.E", lower = 1e11, upper = 3e11 }, { path = "material.rho", lower = 5000.0, upper = 10000.0 })",
      2.1e11, 7800.0);
  const CalibrationOutcome o = calibrate_case(c);
  EXPECT_NEAR((o.values[0] / o.values[1]) / (2.1e11 / 7800.0), 1.0, 1e-5);  // the ratio is found
  ASSERT_FALSE(o.warnings.empty());
  bool flagged = false;
  for (const auto& w : o.warnings)
    flagged =
        flagged || (w.find("do not determine the combination") != std::string::npos &&
                    w.find("log(material.E)") != std::string::npos && w.find("log(material.rho)") != std::string::npos);
  EXPECT_TRUE(flagged);
  EXPECT_TRUE(std::isnan(o.std_devs[0]) && std::isnan(o.std_devs[1])) << "no confident standard deviation";
}

TEST_F(CalibrationRoundTrip, EveryStartOfALatinHypercubeIsReportedAndTheBestWins) {
  const fs::path c =
      write_case(1.5e11, 7800.0, R"({ path = "material.E", lower = 1e11, upper = 3e11 })", 2.1e11, 7800.0);
  std::ofstream(c, std::ios::app) << "starts = 4\nseed = 11\n";
  const CalibrationOutcome o = calibrate_case(c);
  ASSERT_EQ(o.starts.size(), 4u);
  EXPECT_DOUBLE_EQ(o.starts[0].start[0], 1.5e11);  // the case's value first
  for (size_t s = 1; s < 4; ++s) {
    // One start per quarter of [log 1e11, log 3e11]: a Latin hypercube in one dimension.
    const double q = std::log(o.starts[s].start[0] / 1e11) / std::log(3.0) * 3;
    EXPECT_GE(q, 0.0);
    EXPECT_LT(q, 3.0);
    for (size_t t = 1; t < s; ++t)
      EXPECT_NE(std::floor(q), std::floor(std::log(o.starts[t].start[0] / 1e11) / std::log(3.0) * 3));
  }
  for (const CalibrationStart& r : o.starts) EXPECT_GE(r.final_cost, o.starts[o.best].final_cost);
  ASSERT_TRUE(o.converged);
  EXPECT_NEAR(o.values[0] / 2.1e11, 1.0, 1e-6);
}

// Starts solved at once on three workers give the serial outcome bit for bit: every start's values
// and costs, the chosen start, the model runs counted.
TEST_F(CalibrationRoundTrip, StartsInParallelGiveTheSerialOutcomeBitForBit) {
  const fs::path c = write_case(
      1.8e11, 7000.0,
      R"({ path = "material.E", lower = 1e11, upper = 3e11 }, { path = "material.rho", lower = 5000.0, upper = 10000.0 })",
      2.1e11, 7800.0);
  std::ofstream(c, std::ios::app) << "starts = 5\nseed = 3\nthreads = 1\n";
  const CalibrationOutcome serial = calibrate_case(c);
  std::string text;
  {
    std::ifstream in(c);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text.replace(text.find("threads = 1"), 11, "threads = 3");
  std::ofstream(c) << text;
  const CalibrationOutcome parallel = calibrate_case(c);
  ASSERT_EQ(parallel.starts.size(), serial.starts.size());
  for (size_t s = 0; s < serial.starts.size(); ++s) {
    EXPECT_EQ(parallel.starts[s].values, serial.starts[s].values) << "start " << s + 1;
    EXPECT_EQ(parallel.starts[s].final_cost, serial.starts[s].final_cost) << "start " << s + 1;
    EXPECT_EQ(parallel.starts[s].iterations, serial.starts[s].iterations) << "start " << s + 1;
  }
  EXPECT_EQ(parallel.best, serial.best);
  EXPECT_EQ(parallel.values, serial.values);
  EXPECT_EQ(parallel.residual_evaluations, serial.residual_evaluations);
  EXPECT_EQ(parallel.history, serial.history);
}

// calibrated.toml names the case's files (here the reference) relative to the folder it is written
// in, so that it runs there (issue 33: its data paths used to be relative to the input case).
TEST_F(CalibrationRoundTrip, TheCalibratedCaseRunsWhereItIsWritten) {
  const fs::path c =
      write_case(1.5e11, 7800.0, R"({ path = "material.E", lower = 1e11, upper = 3e11 })", 2.1e11, 7800.0);
  const CalibrationOutcome o = calibrate_case(c);
  ASSERT_TRUE(o.converged) << o.termination;
  const fs::path out = dir_ / "reports" / "fit";
  fs::create_directories(out);
  write_calibration_outputs(o, c, 1.0, out, false);
  const CaseSpec calibrated = parse_case_file(out / "calibrated.toml");
  ASSERT_FALSE(calibrated.checks.empty());
  EXPECT_TRUE(fs::equivalent(calibrated.checks.front().reference, dir_ / "reference.csv"));
}

TEST_F(CalibrationRoundTrip, AFitThatDoesNotConvergeSaysSoAndWritesNoCalibratedCase) {
  const fs::path c = one_iteration_case(1.1e11);
  const CalibrationOutcome o = calibrate_case(c);
  ASSERT_FALSE(o.converged) << o.termination;
  fs::create_directories(dir_ / "out");
  std::ofstream(dir_ / "out" / "calibrated.toml") << "stale\n";
  write_calibration_outputs(o, c, 1.0, dir_ / "out", false);
  EXPECT_FALSE(fs::exists(dir_ / "out" / "calibrated.toml"));
  std::ifstream report(dir_ / "out" / "report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("**Not converged**"), std::string::npos);
  bool warned = false;
  for (const auto& w : o.warnings) warned = warned || w.find("did not converge") != std::string::npos;
  EXPECT_TRUE(warned);
}

// An unconverged fit leaves restart.toml, from which `calibrate --restart-from` continues; `--set`
// changes a setting without a copy of the case, here the iteration cap (issue 68).
TEST_F(CalibrationRoundTrip, AnUnconvergedFitIsContinuedFromItsRestartFile) {
  const fs::path c = one_iteration_case(1.1e11);
  const CalibrationOutcome first = calibrate_case(c);
  ASSERT_FALSE(first.converged) << first.termination;
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  write_calibration_outputs(first, c, 1.0, out, false);
  ASSERT_TRUE(fs::exists(out / "restart.toml"));
  EXPECT_FALSE(fs::exists(out / "calibrated.toml"));
  const CalibrationOutcome next =
      calibrate_case(c, {}, {}, nullptr, {{"calibration.max_iterations=50"}, out / "restart.toml"});
  ASSERT_EQ(next.starts.size(), 1u);
  EXPECT_NEAR(next.starts[0].start[0], first.values[0], 1e-9 * first.values[0]);
  EXPECT_LT(next.initial_cost, first.initial_cost);
  ASSERT_TRUE(next.converged) << next.termination;
  EXPECT_NEAR(next.values[0], 2.1e11, 1e-4 * 2.1e11);
  bool said = false;
  for (const auto& w : next.warnings) said = said || w.find("--restart-from") != std::string::npos;
  EXPECT_TRUE(said);
  write_calibration_outputs(next, c, 1.0, out, false);
  EXPECT_TRUE(fs::exists(out / "calibrated.toml"));
  EXPECT_FALSE(fs::exists(out / "restart.toml"));  // not left looking current
}

TEST_F(CalibrationRoundTrip, SetGivesAParameterItsStartAndARestartFileMustHoldEveryParameter) {
  const fs::path c = one_iteration_case(1.5e11);
  EXPECT_EQ(calibrate_case(c, {}, {}, nullptr, {{"material.E=2.5e11"}, {}}).starts[0].start[0], 2.5e11);
  std::ofstream(dir_ / "other.toml") << "[material]\nnu = 0.3\n";
  try {
    calibrate_case(c, {}, {}, nullptr, {{}, dir_ / "other.toml"});
    ADD_FAILURE() << "a restart file without material.E was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("other.toml: no number at the calibration path 'material.E'"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(CalibrationRoundTrip, ParameterOutsideItsBoundsIsAnInputError) {
  const fs::path c = write_case(5e11, 7800.0, R"({ path = "material.E", lower = 1e11, upper = 3e11 })", 2.1e11, 7800.0);
  EXPECT_THROW(calibrate_case(c), InputError);
}

TEST_F(CalibrationRoundTrip, UnknownParameterPathIsAnInputError) {
  const fs::path c = write_case(2e11, 7800.0, R"({ path = "material.G", lower = 1e10, upper = 1e11 })", 2.1e11, 7800.0);
  EXPECT_THROW(calibrate_case(c), InputError);
}

TEST_F(CalibrationRoundTrip, PerCheckUncertaintyMustNameAFittedCheck) {
  const fs::path c = write_case(2e11, 7800.0, R"({ path = "material.E", lower = 1e11, upper = 3e11 })", 2.1e11, 7800.0);
  std::ofstream(c, std::ios::app) << "check_uncertainties = { \"other\" = 0.005 }\n";
  EXPECT_THROW(calibrate_case(c), InputError);
}

TEST_F(CalibrationRoundTrip, PerCheckUncertaintyOverridesTheDefault) {
  const fs::path c = write_case(2e11, 7800.0, R"({ path = "material.E", lower = 1e11, upper = 3e11 })", 2.1e11, 7800.0);
  std::ofstream(c, std::ios::app) << "check_uncertainties = { \"frequencies\" = 0.005 }\n";
  const CaseSpec spec = parse_case_file(c);
  const auto cal = parse_calibration(read_case_table(c), c, spec);
  ASSERT_TRUE(cal.has_value());
  EXPECT_DOUBLE_EQ(uncertainty_of(*cal, "frequencies"), 0.005);
  EXPECT_DOUBLE_EQ(uncertainty_of(*cal, "anything else"), 0.001);
}

}  // namespace
}  // namespace bb
