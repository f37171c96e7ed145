// The measured phase against the model's at the start of a fit (identify/phase_check, issue 68):
// 180 degrees off or of the opposite sign through a resonance is bad input naming the file's
// column; near 180 degrees off where the data pass through no resonance is a warning (a start far
// from the data looks the same); data that agree pass silently.
#include "identify/phase_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "common/errors.hpp"

namespace bb {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Curve {
  CalibrationSpec cal;
  std::vector<FitPoint> points;
};

// Measured phase `measured(model phase)` +-1 degree at 21 frequencies: the model a single mode at
// 100 Hz with 2 % damping over 90-110 Hz (-11 to -168 degrees), or when `flat` at -179 degrees.
template <class Measured>
Curve curve(Measured measured, bool flat = false) {
  Curve c;
  CalibrationData d;
  d.name = "rig";
  d.table = "frf_1";
  d.data.kind = DataKind::frf;
  d.data.file = "data/rig.csv";
  d.data.units["phase"] = Unit{"deg", Dimension::angle, kDeg};
  d.columns = {{"frequency", "frequency_hz"}, {"amplitude", "A.x_amp_m"}, {"phase", "A.x_phase_deg"}};
  c.cal.data = {d};
  for (int k = 0; k <= 20; ++k) {
    const double f = (flat ? 20.0 : 90.0) + k;
    FitPoint p;
    p.set = "rig";
    p.quantity = "phase";
    p.x = f;
    p.computed = flat ? -179.0 * kDeg : std::atan2(-0.0004 * f, 1.0 - f * f / 1e4);
    p.measured = std::remainder(measured(p.computed) + (k % 2 ? 1.0 : -1.0) * kDeg, 2.0 * std::numbers::pi);
    p.sigma = kDeg;
    p.angle = true;
    c.points.push_back(p);
  }
  return c;
}

std::string refusal(const Curve& c) {
  try {
    check_measured_phases(c.cal, c.points);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PhaseCheck, APhaseThroughAResonance180DegreesOffOrReversedIsBadInputNamingTheColumn) {
  const std::string shifted = refusal(curve([](double model) { return model + std::numbers::pi; }));
  EXPECT_NE(shifted.find("calibration data 'rig': column 'phase [deg]' of data/rig.csv is 180 deg off"),
            std::string::npos)
      << shifted;
  const std::string reversed = refusal(curve([](double model) { return -model; }));
  EXPECT_NE(reversed.find("column 'phase [deg]' of data/rig.csv is of the opposite sign"), std::string::npos)
      << reversed;
}

TEST(PhaseCheck, DataThatAgreePassAndAPhaseOffWithoutAResonanceIsAWarning) {
  const Curve right = curve([](double model) { return model; });
  EXPECT_EQ(refusal(right), "accepted");
  EXPECT_TRUE(check_measured_phases(right.cal, right.points).empty());
  // Flat data near -5 degrees against a model at -179: a far start or a phase 180 off.
  const Curve flat = curve([](double) { return -5.0 * kDeg; }, true);
  const std::vector<std::string> w = check_measured_phases(flat.cal, flat.points);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("the start may be far from the data's resonance, or the phase is 180 deg off"), std::string::npos)
      << w[0];
}

}  // namespace
}  // namespace bb
