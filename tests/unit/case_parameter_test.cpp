// Typed case parameters (cases/case_parameter): a dotted path resolves once into a reference that
// reads and writes the parsed case, and a write that makes the case invalid is refused as the
// parser would refuse it.
#include "cases/case_parameter.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <numbers>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "forced/hbm_level.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "two_blade_rom_case.hpp"

namespace bb {
namespace {

CaseSpec oscillator() { return parse_case_table(toml::parse(test::oscillator_case_text({})), "oscillator.toml"); }

// Two DOFs coupled by a spring (K has off-diagonal entries).
CaseSpec coupled_pair() {
  return parse_case_table(
      toml::parse("[case]\nname = \"b\"\n[analysis]\ntype = \"hbm\"\nfrequency_hz = [100.0, 200.0]\nstep_hz = "
                  "1.0\nmodal_damping = 0.01\nforces = [{ dof = \"A.x\", amplitude = 1.0 }]\nforce_levels = [1.0]\n"
                  "responses = [\"A.x\"]\n[analysis.model]\nname = \"b\"\ndofs = [\"A.x\", \"B.x\"]\n"
                  "stiffness = [[1.1e6, -1.0e5], [-1.0e5, 1.1e6]]\nmass = [[1.0, 0.0], [0.0, 1.0]]\n"
                  "[[analysis.contact]]\nname = \"c\"\ntangential = { \"A.x\" = 1.0 }\nkn = 1.0e6\nkt = 1.0e6\n"
                  "mu = 0.3\nn0 = 30.0\n"),
      "blades.toml");
}

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
  EXPECT_EQ(std::get<HbmSpec>(spec.analysis).contacts[0].point.kt, 2.0e6);
  EXPECT_EQ(std::get<HbmSpec>(spec.analysis).damping.zeta, 0.02);
}

TEST(CaseParameter, PathsOfAnUnknownFormOrAbsentFromTheCaseAreRefused) {
  for (const char* bad : {"analysis.contact.0.Kt", "analysis.model.mass", "material", "mesh.dimensions.nonsense",
                          "analysis.contact.x.kt"})
    EXPECT_THROW((void)parse_parameter_path(bad), std::invalid_argument) << bad;
  const CaseSpec spec = oscillator();
  // A key no law has (only the contact's law knows its own keys) is refused against the case.
  for (const char* absent : {"analysis.contact.1.kt", "analysis.damper.kt", "mesh.dimensions.L_a", "material.E",
                             "analysis.forces.3.amplitude", "analysis.contact.0.kx"})
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
  CaseSpec two = coupled_pair();
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

namespace bb {
namespace {

// A modal joint model as a modal test gives it: two modes (frequency, modal mass, damping per
// mode) and an Iwan joint on the first modal coordinate.
CaseSpec modal_joint() {
  return parse_case_table(
      toml::parse("[case]\nname = \"joint\"\n[analysis]\ntype = \"hbm\"\nfrequency_hz = [70.0, 90.0]\nstep_hz = "
                  "0.5\nmodal_damping = [0.0015, 0.004]\nforces = [{ dof = \"A.x\", amplitude = 1.0 }]\n"
                  "force_levels = [0.1]\nresponses = [\"A.x\"]\n[analysis.model]\nname = \"modes\"\n"
                  "dofs = [\"A.x\", \"B.x\"]\nfrequency_hz = [78.0, 240.0]\nmodal_mass = [1.0, 0.5]\n"
                  "[[analysis.contact]]\nname = \"joint\"\ntangential = { \"A.x\" = 1.0 }\nlaw = \"iwan\"\n"
                  "kt = 5.0e3\nmu = 0.5\nn0 = 0.5\nchi = -0.5\nbeta = 0.2\nsliders = 16\n"),
      "joint.toml");
}

TEST(CaseParameter, AModalModelsFrequencyAndModalMassAreItsOwnWhicheverIsSetFirst) {
  const CaseSpec spec = modal_joint();
  const CaseParameter f0 = parse_parameter_path("analysis.model.frequency_hz.0");
  const CaseParameter m0 = parse_parameter_path("analysis.model.modal_mass.0");
  EXPECT_NEAR(parameter_value(spec, f0), 78.0, 1e-12);
  EXPECT_EQ(parameter_value(spec, m0), 1.0);
  EXPECT_NEAR(parameter_value(spec, parse_parameter_path("analysis.model.frequency_hz.1")), 240.0, 1e-12);
  CaseSpec a = spec, b = spec;
  set_parameter_value(a, f0, 80.0);
  set_parameter_value(a, m0, 2.0);
  set_parameter_value(b, m0, 2.0);
  set_parameter_value(b, f0, 80.0);
  for (const CaseSpec* s : {&a, &b}) {
    const ReducedModel& m = *std::get<HbmSpec>(s->analysis).model.matrices;
    EXPECT_EQ(m.mass(0, 0), 2.0);
    EXPECT_NEAR(m.stiffness(0, 0) / (2.0 * std::pow(2.0 * std::numbers::pi * 80.0, 2)), 1.0, 1e-14);
    EXPECT_NEAR(parameter_value(*s, f0), 80.0, 1e-12);
    EXPECT_EQ(m.mass(1, 1), 0.5);  // the other mode is untouched
  }
  EXPECT_THROW(set_parameter_value(a, f0, -1.0), InputError);
  EXPECT_THROW((void)parameter_value(spec, parse_parameter_path("analysis.model.frequency_hz.2")),
               std::invalid_argument);
  // A lumped model whose DOFs are coupled has no modal frequency per DOF.
  CaseSpec two = coupled_pair();
  try {
    (void)parameter_value(two, f0);
    ADD_FAILURE() << "a coupled DOF has no modal frequency";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("coupled"), std::string::npos) << e.what();
  }
}

TEST(CaseParameter, PerModeDampingIsNamedByItsModeAndTheScalarFormRefusesAnIndex) {
  CaseSpec spec = modal_joint();
  const CaseParameter z1 = parse_parameter_path("analysis.modal_damping.1");
  EXPECT_EQ(parameter_value(spec, z1), 0.004);
  set_parameter_value(spec, z1, 0.006);
  EXPECT_EQ(std::get<HbmSpec>(spec.analysis).damping.mode_zetas, (std::vector<double>{0.0015, 0.006}));
  EXPECT_THROW((void)parameter_value(spec, parse_parameter_path("analysis.modal_damping")), std::invalid_argument);
  EXPECT_THROW((void)parameter_value(spec, parse_parameter_path("analysis.modal_damping.2")), std::invalid_argument);
  EXPECT_THROW((void)parameter_value(oscillator(), z1), std::invalid_argument);  // one ratio for every mode
  ASSERT_TRUE(hbm_parameter(z1));
  EXPECT_EQ(hbm_parameter(z1)->kind, HbmParameter::Kind::mode_damping);
  EXPECT_EQ(hbm_parameter(z1)->row, 1u);
  EXPECT_FALSE(unsupported_sensitivity(std::get<HbmSpec>(spec.analysis), *hbm_parameter(z1)));
  EXPECT_TRUE(unsupported_sensitivity(std::get<HbmSpec>(oscillator().analysis), *hbm_parameter(z1)));
}

TEST(CaseParameter, AnIwanJointsChiAndBetaAreCalibrationPathsAJenkinsContactLacks) {
  CaseSpec spec = modal_joint();
  const CaseParameter chi = parse_parameter_path("analysis.contact.0.chi");
  const CaseParameter beta = parse_parameter_path("analysis.contact.0.beta");
  EXPECT_EQ(parameter_value(spec, chi), -0.5);
  EXPECT_EQ(parameter_value(spec, beta), 0.2);
  set_parameter_value(spec, chi, -0.25);
  const auto& law = std::get<HbmSpec>(spec.analysis).contacts[0].distribution;
  EXPECT_EQ(law->parameter("chi"), -0.25);
  EXPECT_EQ(law->shares().size(), 16u);
  EXPECT_THROW(set_parameter_value(spec, chi, 0.5), InputError);  // outside (-1, 0]
  EXPECT_THROW((void)parameter_value(spec, parse_parameter_path("analysis.contact.0.gamma")), std::invalid_argument);
  EXPECT_THROW((void)parameter_value(oscillator(), chi), std::invalid_argument);  // a Jenkins contact
  EXPECT_FALSE(hbm_parameter(chi));
  EXPECT_THROW((void)parse_parameter_path("analysis.contact.0.Chi"), std::invalid_argument);
}

// Two nonlinear modes as [[analysis.mode]], and one mode in the single-mode form.
CaseSpec two_nonlinear_modes() {
  return parse_case_table(
      toml::parse("[case]\nname = \"m\"\n[analysis]\ntype = \"nonlinear_modal\"\ndof = \"A.x\"\n"
                  "[[analysis.mode]]\nmass = 1.0\nbackbone = { amplitude_m = [1e-5, 1e-4], frequency_hz = [100.0, "
                  "99.6], damping_ratio = [0.002, 0.005] }\n[[analysis.mode]]\nmass = 1.5\n[analysis.mode.backbone]\n"
                  "amplitude_m = [2e-5]\nfrequency_hz = [103.0]\ndamping_ratio = [0.003]\n"
                  "[[analysis.response_control]]\nname = \"rc\"\ndof = \"A.x\"\ndisplacement = 2e-5\n"
                  "frequency_hz = [96.0, 106.0]\nstep_hz = 1.0\n"),
      "modes.toml");
}

TEST(CaseParameter, EachNonlinearModeOfAnArrayIsNamedByItsIndexAndTheSingleFormByNone) {
  CaseSpec spec = two_nonlinear_modes();
  const struct {
    const char* path;
    double value;
  } expected[] = {{"analysis.mode.0.backbone.frequency_hz.1", 99.6},
                  {"analysis.mode.0.backbone.damping_ratio.0", 0.002},
                  {"analysis.mode.1.backbone.frequency_hz.0", 103.0},
                  {"analysis.mode.1.mass", 1.5}};
  for (const auto& e : expected) {
    const CaseParameter p = parse_parameter_path(e.path);
    EXPECT_EQ(parameter_value(spec, p), e.value) << e.path;
    set_parameter_value(spec, p, 1.01 * e.value);
    EXPECT_EQ(parameter_value(spec, p), 1.01 * e.value) << e.path;
  }
  const auto& modes = std::get<NonlinearModalSpec>(spec.analysis).modes;
  EXPECT_EQ(modes[1].mass, 1.01 * 1.5);
  EXPECT_EQ(modes[0].frequency_hz.values()[1], 1.01 * 99.6);
  for (const char* absent : {"analysis.mass", "analysis.backbone.frequency_hz.0", "analysis.mode.2.mass",
                             "analysis.mode.1.backbone.damping_ratio.1"})
    EXPECT_THROW((void)parameter_value(spec, parse_parameter_path(absent)), std::invalid_argument) << absent;
  for (const char* bad : {"analysis.mode.x.mass", "analysis.mode.0", "analysis.mode.0.backbone.f.0"})
    EXPECT_THROW((void)parse_parameter_path(bad), std::invalid_argument) << bad;
  // The single-mode form has no mode index.
  CaseSpec one = parse_case_table(
      toml::parse("[case]\nname = \"m\"\n[analysis]\ntype = \"nonlinear_modal\"\ndof = \"A.x\"\nmass = 2.0\n"
                  "[analysis.backbone]\namplitude_m = [2e-5]\nfrequency_hz = [103.0]\ndamping_ratio = [0.003]\n"),
      "one.toml");
  EXPECT_EQ(parameter_value(one, parse_parameter_path("analysis.mass")), 2.0);
  EXPECT_THROW((void)parameter_value(one, parse_parameter_path("analysis.mode.0.mass")), std::invalid_argument);
}

}  // namespace
}  // namespace bb
