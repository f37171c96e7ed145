// Typed case parameters (cases/case_parameter): a dotted path resolves once into a reference that
// reads and writes the parsed case, and a write that makes the case invalid is refused as the
// parser would refuse it.
#include "cases/case_parameter.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "oscillator_case.hpp"

namespace bb {
namespace {

CaseSpec oscillator() { return parse_case_table(toml::parse(test::oscillator_case_text({})), "oscillator.toml"); }

TEST(CaseParameter, EveryContactLawPathReadsAndWritesItsField) {
  CaseSpec spec = oscillator();
  const struct {
    const char* path;
    double value;
  } expected[] = {{"analysis.contact.0.kn", 1.0e6}, {"analysis.contact.0.kt", 1.0e6},
                  {"analysis.contact.0.mu", 0.3},   {"analysis.contact.0.n0", 30.0},
                  {"analysis.modal_damping", 0.01}, {"analysis.forces.0.amplitude", 1.0}};
  for (const auto& e : expected) {
    const CaseParameter p = parse_parameter_path(e.path);
    EXPECT_EQ(parameter_value(spec, p), e.value) << e.path;
    set_parameter_value(spec, p, 2.0 * e.value);
    EXPECT_EQ(parameter_value(spec, p), 2.0 * e.value) << e.path;
  }
  EXPECT_EQ(std::get<HbmSpec>(spec.analysis).contacts[0].law.kt, 2.0e6);
  EXPECT_EQ(std::get<HbmSpec>(spec.analysis).damping.zeta, 0.02);
}

TEST(CaseParameter, PathsOfAnUnknownFormOrAbsentFromTheCaseAreRefused) {
  for (const char* bad : {"analysis.contact.0.kx", "analysis.model.mass", "material", "mesh.dimensions.nonsense",
                          "analysis.contact.x.kt"})
    EXPECT_THROW((void)parse_parameter_path(bad), std::invalid_argument) << bad;
  const CaseSpec spec = oscillator();
  for (const char* absent : {"analysis.contact.1.kt", "analysis.damper.kt", "mesh.dimensions.L_a", "material.E",
                             "analysis.forces.3.amplitude"})
    EXPECT_THROW((void)parameter_value(spec, parse_parameter_path(absent)), std::invalid_argument) << absent;
}

TEST(CaseParameter, AWriteThatBreaksTheContactLawIsAnInputError) {
  CaseSpec spec = oscillator();
  EXPECT_THROW(set_parameter_value(spec, parse_parameter_path("analysis.contact.0.mu"), -1.0), InputError);
}

TEST(CaseParameter, HbmSensitivitiesCoverTheLawsAndTheModalDampingButNotTheDamperSeat) {
  EXPECT_TRUE(hbm_parameter(parse_parameter_path("analysis.contact.2.n0")));
  EXPECT_EQ(hbm_parameter(parse_parameter_path("analysis.contact.2.n0"))->contact, 2u);
  EXPECT_TRUE(hbm_parameter(parse_parameter_path("analysis.damper.mu")));
  EXPECT_TRUE(hbm_parameter(parse_parameter_path("analysis.modal_damping")));
  EXPECT_FALSE(hbm_parameter(parse_parameter_path("analysis.damper.kn")));  // moves the static seat
  EXPECT_FALSE(hbm_parameter(parse_parameter_path("analysis.forces.0.amplitude")));
  EXPECT_FALSE(hbm_parameter(parse_parameter_path("material.E")));
}

}  // namespace
}  // namespace bb
