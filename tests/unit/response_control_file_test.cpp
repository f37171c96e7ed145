// A response control read from its measured curve (`file =`, issue 68): the frequencies as
// stepped and the level as the median of the amplitude column, in the quantity the column holds,
// with its spread; a level the data do not show is refused (tests/bad_input/ holds the refusals).
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "oscillator_case.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

class ResponseControlFile : public test::TempFolderTest {
 protected:
  HbmSpec parse(const std::string& control) {
    test::OscillatorCase c;
    c.analysis_extra = "[[analysis.response_control]]\nname = \"rc\"\ndof = \"A.x\"\n" + control;
    return std::get<HbmSpec>(parse_case_file(write(test::oscillator_case_text(c))).analysis);
  }
};

TEST_F(ResponseControlFile, TheLevelIsTheMedianOfTheAmplitudeColumnInItsOwnQuantity) {
  write(
      "frequency [Hz], amplitude [mm/s^2], force [N]\n"
      "160, 20100, 0.3\n158, 19900, 0.25\n157, 20000, 0.2\n156, 20300, 0.22\n150, 19800, 0.3\n",
      "rc.csv");
  const HbmSpec spec = parse("file = \"rc.csv\"\n");
  ASSERT_EQ(spec.response_controls.size(), 1u);
  const ResponseControlSpec& c = spec.response_controls[0];
  EXPECT_EQ(c.derivative, 2);  // an acceleration
  EXPECT_NEAR(c.amplitude, 20.0, 1e-12);
  EXPECT_EQ(c.frequency_hz, (std::vector<double>{160.0, 158.0, 157.0, 156.0, 150.0}));  // as stepped: down
  EXPECT_NEAR(c.spread_low, -0.01, 1e-12);
  EXPECT_NEAR(c.spread_high, 0.015, 1e-12);
  EXPECT_NE(c.file.find("rc.csv"), std::string::npos);
  // The same level stated in the case is accepted; a velocity or another level is not.
  EXPECT_NEAR(parse("file = \"rc.csv\"\nacceleration = 20.5\n").response_controls[0].amplitude, 20.0, 1e-12);
  EXPECT_THROW(parse("file = \"rc.csv\"\nvelocity = 20.0\n"), InputError);
  EXPECT_THROW(parse("file = \"rc.csv\"\nacceleration = 25.0\n"), InputError);
  EXPECT_THROW(parse("file = \"rc.csv\"\nfrequency_hz = [150.0, 160.0]\n"), InputError);
  EXPECT_THROW(parse("file = \"rc.csv\"\nlevel_tolerance = 0.01\n"), InputError);  // 156 Hz lies 1.5 % off
  EXPECT_THROW(parse("acceleration = 20.0\nfrequency_hz = [150.0, 160.0]\nlevel_tolerance = 0.1\n"), InputError);
}

}  // namespace
}  // namespace bb
