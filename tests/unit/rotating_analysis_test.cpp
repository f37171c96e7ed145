// The rotating analysis through the case pipeline (analysis/rotating_analysis): the spectrum that
// measures oscillation frequencies, the tables a run writes, the modes at rest against the modal
// analysis of the same mesh, and a diverging run that must fail the case with its time.
#include "analysis/rotating_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/modal_analysis.hpp"
#include "cases/case_spec.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "model/build_model.hpp"
#include "pipeline/run_case.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

TEST(AmplitudeSpectrum, FindsTheFrequencyAndAmplitudeOfASinusoidBetweenItsBins) {
  const double dt = 1e-4, f = 191.37, a = 2.5e-5;
  Eigen::VectorXd x(50000);
  for (Eigen::Index i = 0; i < x.size(); ++i)
    x[i] = 1e-3 + a * std::sin(kTwoPi * f * static_cast<double>(i) * dt + 0.3) +
           0.2 * a * std::sin(kTwoPi * 47.7 * static_cast<double>(i) * dt);
  const AmplitudeSpectrum s(x, dt);
  const SpectralPeak p = s.peak(0.97 * f, 1.03 * f);
  EXPECT_NEAR(p.frequency_hz, f, 0.1 * s.resolution_hz());
  EXPECT_NEAR(p.amplitude, a, 0.01 * a);
  // Away from every component only the window's leakage is left: what the analysis treats as "not excited".
  EXPECT_LT(s.peak(300.0, 320.0).amplitude, 1e-6 * a);
}

// A slender steel strip (plane stress) spun about its root: small, quick.
std::string strip_case(const std::string& analysis) {
  return R"([case]
name = "strip"
[material]
E = 2.0e11
nu = 0.3
rho = 7800.0
[section]
thickness = 0.01
[mesh]
kind = "mapped_quad"
element = "q4"
corners = [[0.0, 0.0], [0.5, 0.0], [0.5, 0.02], [0.0, 0.02]]
nx = 25
ny = 2
[sets.root]
x = 0.0
[sets.tip]
x = 0.5
y = 0.01
[[bc]]
set = "root"
dofs = ["x", "y"]
[analysis]
type = "rotating"
axis = { point = [-0.1, 0.01] }
histories = ["tip"]
)" + analysis;
}

class RotatingAnalysis : public test::TempFolderTest {};

TEST_F(RotatingAnalysis, ModesAtRestAreThoseOfTheModalAnalysisOfTheSameMesh) {
  const CaseSpec spec = parse_case_file(write(strip_case("speed_rad_s = 200.0\nend_time_s = 0.02\n")));
  const Model model = build_model(spec.model);
  const RotatingOutcome o = run_rotating(model, std::get<RotatingSpec>(spec.analysis));
  const ModalResult modal = solve_modal(model, ModeSelection{4, std::nullopt, std::nullopt}, ModalOptions{});
  const ResultTable& t = o.tables.at("rotating_modes");
  for (int m = 0; m < 4; ++m)
    EXPECT_NEAR(t.values(m, *t.column_index("rest_hz")), modal.frequencies_hz[m], 1e-6 * modal.frequencies_hz[m])
        << "mode " << m + 1;
  // Stiffening raises the first (chordwise) mode with speed despite the softening: 200 rad/s.
  EXPECT_GT(t.values(0, *t.column_index("frequency_hz")), t.values(0, *t.column_index("rest_hz")));
  for (const char* name :
       {"histories", "deflection", "oscillation", "energy", "campbell", "crossings", "rotating_cost"})
    EXPECT_TRUE(o.tables.count(name)) << name;
  const ResultTable& h = o.tables.at("histories");
  EXPECT_TRUE(h.column_index("tip.ux_m") && h.column_index("tip.uy_m") && h.column_index("omega_rad_s"));
}

TEST_F(RotatingAnalysis, ARunThatDivergesFailsTheCaseNamingTheTime) {
  // Without stiffening, far above the strip's first bending frequency (about 65 rad/s): spin softening wins.
  const std::filesystem::path file =
      write(strip_case("speed_rad_s = 2000.0\nend_time_s = 1.0\ntime_step_s = 1e-4\nstiffening = false\n"
                       "[analysis.campbell]\nspeeds_rad_s = [0.0, 10.0]\n"));
  const RunOutcome o = run_case(file, {.out_dir = dir_ / "out", .study = false, .plots = false});
  EXPECT_EQ(o.record.status, RunStatus::solver_failed) << o.record.message;
  EXPECT_NE(o.record.message.find("t = "), std::string::npos) << o.record.message;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "histories.csv"));
}

TEST_F(RotatingAnalysis, RunsWithoutHistoriesAndMeasuresNoOscillation) {
  std::string text = strip_case("speed_rad_s = 200.0\nend_time_s = 0.02\n");
  text.erase(text.find("histories = [\"tip\"]\n"), std::string("histories = [\"tip\"]\n").size());
  const CaseSpec spec = parse_case_file(write(text));
  const RotatingOutcome o = run_rotating(build_model(spec.model), std::get<RotatingSpec>(spec.analysis));
  EXPECT_EQ(o.tables.at("deflection").values.rows(), 0);
  EXPECT_FALSE(o.tables.count("oscillation"));  // no history: nothing to measure
  EXPECT_TRUE(o.tables.count("campbell") && o.tables.count("energy"));
}

TEST_F(RotatingAnalysis, AnAutomaticStepIsHeldToTheStepLimitOfAGivenOne) {
  // 40 steps per period of the lowest rotating mode: about 1e9 steps over 1e5 s.
  const CaseSpec spec = parse_case_file(write(strip_case("speed_rad_s = 200.0\nend_time_s = 1e5\n")));
  try {
    run_rotating(build_model(spec.model), std::get<RotatingSpec>(spec.analysis));
    FAIL() << "not refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'analysis.end_time_s'"), std::string::npos) << what;
    EXPECT_NE(what.find("exceed the limit of 5e+07 steps"), std::string::npos) << what;
  }
}

TEST_F(RotatingAnalysis, ARunAboveTheWorkBoundIsRefusedWithItsEstimate) {
  const CaseSpec spec = parse_case_file(write(strip_case("speed_rad_s = 200.0\nend_time_s = 0.02\n")));
  const Model model = build_model(spec.model);
  WorkLimits limits;
  limits.operations = 1e3;  // far below the few hundred steps of this run
  try {
    run_rotating(model, std::get<RotatingSpec>(spec.analysis), limits);
    FAIL() << "not refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("floating-point operations"), std::string::npos) << what;
    EXPECT_NE(what.find("steps of"), std::string::npos) << what;
  }
  limits.operations = 1e12;
  limits.bytes = 1e3;  // and the memory bound, for the histories
  EXPECT_THROW(run_rotating(model, std::get<RotatingSpec>(spec.analysis), limits), InputError);
}

}  // namespace
}  // namespace bb
