// Typed case parameters (cases/case_parameter): a dotted path resolves once into a reference that
// reads and writes the parsed case, and a write that makes the case invalid is refused as the
// parser would refuse it.
#include "cases/case_parameter.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "forced/hbm_level.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "two_blade_rom_case.hpp"

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

TEST(CaseParameter, LumpedMatrixEntriesAreWrittenSymmetrically) {
  CaseSpec spec = oscillator();  // k = 1e6 N/m, m = 1 kg
  const CaseParameter k00 = parse_parameter_path("analysis.model.stiffness.0.0");
  const CaseParameter m00 = parse_parameter_path("analysis.model.mass.0.0");
  EXPECT_EQ(parameter_value(spec, k00), 1.0e6);
  EXPECT_EQ(parameter_value(spec, m00), 1.0);
  set_parameter_value(spec, k00, 2.0e6);
  set_parameter_value(spec, m00, 3.0);
  const ReducedModel& rom = *std::get<HbmSpec>(spec.analysis).model.matrices;
  EXPECT_EQ(rom.stiffness(0, 0), 2.0e6);
  EXPECT_EQ(rom.mass(0, 0), 3.0);
  EXPECT_THROW((void)parameter_value(spec, parse_parameter_path("analysis.model.stiffness.1.0")),
               std::invalid_argument);  // one DOF
  for (const char* bad : {"analysis.model.stiffness.0", "analysis.model.mass.a.0", "analysis.model.damping.0.0"})
    EXPECT_THROW((void)parse_parameter_path(bad), std::invalid_argument) << bad;
  // An off-diagonal entry moves its mirror.
  CaseSpec two = parse_case_table(
      toml::parse("[case]\nname = \"b\"\n[analysis]\ntype = \"hbm\"\nfrequency_hz = [100.0, 200.0]\nstep_hz = "
                  "1.0\nmodal_damping = 0.01\nforces = [{ dof = \"A.x\", amplitude = 1.0 }]\nforce_levels = [1.0]\n"
                  "responses = [\"A.x\"]\n[analysis.model]\nname = \"b\"\ndofs = [\"A.x\", \"B.x\"]\n"
                  "stiffness = [[1.1e6, -1.0e5], [-1.0e5, 1.1e6]]\nmass = [[1.0, 0.0], [0.0, 1.0]]\n"
                  "[[analysis.contact]]\nname = \"c\"\ntangential = { \"A.x\" = 1.0 }\nkn = 1.0e6\nkt = 1.0e6\n"
                  "mu = 0.3\nn0 = 30.0\n"),
      "blades.toml");
  set_parameter_value(two, parse_parameter_path("analysis.model.stiffness.0.1"), -2.0e5);
  const ReducedModel& r2 = *std::get<HbmSpec>(two.analysis).model.matrices;
  EXPECT_EQ(r2.stiffness(0, 1), -2.0e5);
  EXPECT_EQ(r2.stiffness(1, 0), -2.0e5);
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

// G's x decides how CF is shared between the flat face's points L1 and L2 (the moment balance):
// moving G away from R, towards the lower point L1, loads L1 more, while the loads still balance
// CF along y whatever G.
TEST(CaseParameter, TheDamperCentreSharesTheCentrifugalForceBetweenItsPoints) {
  CaseSpec spec = parse_case_table(toml::parse(test::two_blade_rom_case_text({})), "two_blade_rom.toml");
  const CaseParameter x = parse_parameter_path("analysis.damper.centre.0");
  const CaseParameter y = parse_parameter_path("analysis.damper.centre.1");
  EXPECT_EQ(parameter_value(spec, x), 0.0415);
  EXPECT_EQ(parameter_value(spec, y), 0.0345);
  const auto loads = [&](double gx) {
    set_parameter_value(spec, x, gx);
    const HbmSpec& hbm = std::get<HbmSpec>(spec.analysis);
    const PreparedHbm p = prepare_hbm(build_model(spec.model), hbm);
    const Eigen::VectorXd n = p.damper_static->normal_preload;  // L1, L2, R
    double vertical = 0.0;
    for (size_t c = 0; c < p.damper->contacts.size(); ++c)
      vertical += n[static_cast<Eigen::Index>(c)] * p.damper->contacts[c].normal.y();
    EXPECT_NEAR(vertical + hbm.damper->centrifugal_force, 0.0, 1e-9 * hbm.damper->centrifugal_force);
    return n;
  };
  const Eigen::VectorXd right = loads(0.0425), left = loads(0.0405);
  EXPECT_GT(left[0] / (left[0] + left[1]), right[0] / (right[0] + right[1]));
  EXPECT_EQ(std::get<HbmSpec>(spec.analysis).damper->centre[0], 0.0405);
  EXPECT_THROW((void)parse_parameter_path("analysis.damper.centre.2"), std::invalid_argument);
}

}  // namespace
}  // namespace bb
