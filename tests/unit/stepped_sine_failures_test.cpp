// A frequency of a stepped sine where the model found no solution (issue 68) stays in its table as
// a row of NaN with the solver's reason, is said in the run's warnings, makes a fitted point there
// a failed evaluation (no value to interpolate over its neighbours), and at the start of a fit
// stops it with the frequency and the reason (SolverError, exit 3).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/hbm_analysis.hpp"
#include "analysis/hbm_stepped_sines.hpp"
#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "identify/fit_points.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "report/describe_hbm.hpp"
#include "report/run_record.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

class SteppedSineFailures : public test::TempFolderTest {
 protected:
  // The stuck oscillator stepped down over five frequencies, then its third point (225 Hz) made a
  // failure as the solver records one.
  void SetUp() override {
    test::TempFolderTest::SetUp();
    test::OscillatorCase c;
    c.levels = "[0.01]";
    c.analysis_extra =
        "[[analysis.stepped_sine]]\nname = \"down\"\nfrequency_hz = [230.0, 226.0, 225.0, 224.0, 210.0]\n"
        "force = [0.02, 0.015, 0.005, 0.01, 0.012]\n";
    spec_ = std::get<HbmSpec>(parse_case_file(write(test::oscillator_case_text(c))).analysis);
    outcome_ = run_hbm(build_model(parse_case_file(dir_ / "case.toml").model), spec_);
    HbmSteppedSine& s = outcome_.stepped_sines.at(0);
    ASSERT_EQ(s.frequency_hz.size(), 5u);
    const auto drop = [](auto& v) { v.erase(v.begin() + 2); };
    drop(s.point), drop(s.frequency_hz), drop(s.force), drop(s.residual), drop(s.iterations);
    for (Eigen::MatrixXd* m : {&s.amplitude, &s.phase_deg, &s.excursion}) {
      Eigen::MatrixXd kept(4, m->cols());
      kept << m->topRows(2), m->bottomRows(2);
      *m = kept;
    }
    s.failed_hz = {225.0};
    s.failures = {"Newton stopped at |R| = 3.2e-3 N at 225 Hz"};
    outcome_.tables.clear();
    add_stepped_sine_tables(outcome_.prepared, spec_, outcome_.stepped_sines, outcome_.tables);
  }

  CalibrationData data_at(const std::string& rows) {
    CalibrationData d;
    d.name = "down";
    d.table = "frf_down";
    d.data = read_measured_data(write("frequency [Hz], amplitude [m]\n" + rows, "down.csv"), DataKind::frf);
    d.columns = {{"frequency", "frequency_hz"}, {"amplitude", "A.x_amp_m"}};
    return d;
  }

  HbmSpec spec_;
  HbmOutcome outcome_;
};

TEST_F(SteppedSineFailures, AFailedPointStaysInItsTableAsARowOfNaNWithTheReason) {
  const ResultTable& t = outcome_.tables.at("frf_down");
  ASSERT_EQ(t.values.rows(), 5);
  const int amp = *t.column_index("A.x_amp_m"), hz = *t.column_index("frequency_hz");
  EXPECT_EQ(t.values(2, 0), 3.0);  // point 3, in the order stepped
  EXPECT_EQ(t.values(2, hz), 225.0);
  EXPECT_EQ(t.values(2, *t.column_index("force_n")), 0.005);
  EXPECT_TRUE(std::isnan(t.values(2, amp)));
  EXPECT_TRUE(std::isfinite(t.values(1, amp)) && std::isfinite(t.values(3, amp)));
  ASSERT_EQ(t.text_columns, std::vector<std::string>{"failure"});
  EXPECT_EQ(t.text[0][2], "Newton stopped at |R| = 3.2e-3 N at 225 Hz");
  EXPECT_EQ(t.text[0][1], "");
}

TEST_F(SteppedSineFailures, AMeasuredPointThereHasNoComputedValueNotItsNeighboursInterpolation) {
  const CalibrationData d = data_at("226, 1e-8\n225, 1e-8\n224.5, 1e-8\n224, 1e-8\n");
  const std::vector<FitPoint> points = data_points(d, outcome_.tables);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_TRUE(std::isfinite(points[0].computed));  // on a solved row next to the failed one
  EXPECT_TRUE(std::isnan(points[1].computed));
  EXPECT_TRUE(std::isnan(points[2].computed));  // between the failed point and a solved one
  EXPECT_TRUE(std::isfinite(points[3].computed));
  CalibrationSpec cal;
  cal.data = {d};
  try {
    require_solved_points(points, cal, outcome_.tables);
    FAIL() << "a fit would start without the model's value at 225 Hz";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("no solution at 225 Hz of table 'frf_down', next to the measured amplitude "
                                         "at 225 Hz (Newton stopped at |R| = 3.2e-3 N at 225 Hz)"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(SteppedSineFailures, TheRunSaysWhichFrequenciesHaveNoSolution) {
  RunRecord run;
  describe(spec_, outcome_, run);
  bool said = false;
  for (const std::string& w : run.warnings)
    said = said || w.find(
                       "stepped sine 'down': no solution at 1 of 5 frequencies (225 Hz; at 225 Hz: Newton "
                       "stopped at |R| = 3.2e-3 N at 225 Hz): rows of NaN in table frf_down") != std::string::npos;
  EXPECT_TRUE(said);
}

}  // namespace
}  // namespace bb
