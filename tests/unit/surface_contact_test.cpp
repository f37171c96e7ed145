// Penalty contact between solid bodies (contact/surface_contact, contact/static_contact) and the
// modes about a contact state (analysis/contact_modal_analysis), against closed forms: two blocks
// pressed by an interference (springs in series: the blocks' E A / L and the penalty layer kn A), a
// tilted gap that closes part of the interface, and the axial modes of a bar held by its contact
// with a clamped block (fixed-spring bar, tan(beta L) = -E A beta / K) and its glued limit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/contact_modal_analysis.hpp"
#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "contact/static_contact.hpp"
#include "contact/surface_contact.hpp"
#include "mesh/hex_block.hpp"
#include "model/contact_pairs.hpp"
#include "pipeline/run_case.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

constexpr double kYoungs = 2.0e11;

HexBlockSpec box(double x1, double y1, double z0, double z1, int nx, int ny, int nz, ElementType type) {
  HexBlockSpec b;
  const double x[8] = {0, x1, x1, 0, 0, x1, x1, 0}, y[8] = {0, 0, y1, y1, 0, 0, y1, y1};
  for (int c = 0; c < 8; ++c) b.corners[c] = Eigen::Vector3d(x[c], y[c], c < 4 ? z0 : z1);
  b.nx = nx;
  b.ny = ny;
  b.nz = nz;
  b.element = type;
  return b;
}

// Block A = [0, a]^2 x [0, la] under block B = [0, a]^2 x [la, la + lb], not merged; node sets
// "a_top", "b_bottom", "a_bottom", "b_top", "x0", "y0"; the pair "interface" (a_top against b_bottom).
Model two_blocks(ElementType type, double a, double la, double lb, int n, double nu) {
  Model m;
  std::vector<std::vector<int>> origin;
  m.mesh = concatenate_meshes({generate_hex_block(box(a, a, 0, la, n, n, n, type)),
                               generate_hex_block(box(a, a, la, la + lb, n, n, n, type))},
                              &origin);
  m.section = {.youngs_modulus = kYoungs, .poisson_ratio = nu, .density = 7800.0};
  auto select = [&](const std::string& name, int body, int axis, double value) {
    for (int node : origin[static_cast<size_t>(body)])
      if (std::abs(m.mesh.coords(node, axis) - value) < 1e-12) m.node_sets[name].push_back(node);
    std::sort(m.node_sets[name].begin(), m.node_sets[name].end());
  };
  select("a_top", 0, 2, la);
  select("b_bottom", 1, 2, la);
  select("a_bottom", 0, 2, 0.0);
  select("b_top", 1, 2, la + lb);
  for (int body = 0; body < 2; ++body) {
    select("x0", body, 0, 0.0);
    select("y0", body, 1, 0.0);
  }
  ContactPairSpec spec{.name = "interface", .contact = "a_top", .target = "b_bottom", .interference = true, .at = {}};
  m.contact_pairs.push_back(build_contact_pair(m, spec));
  return m;
}

struct Pressed {
  StaticContactSolution solution;
  std::vector<ContactPoint> points;
};

Pressed press(const Model& m, double kn, const Eigen::VectorXd& gap) {
  const DofMap dofs = number_dofs(m);
  const GlobalMatrices k = assemble(m.mesh, m.section, {.stiffness = true, .mass = false});
  Pressed p;
  p.points = contact_points(m.mesh, m.contact_pairs);
  ContactPenalty penalty{Eigen::VectorXd::Constant(static_cast<Eigen::Index>(p.points.size()), kn),
                         Eigen::VectorXd::Constant(static_cast<Eigen::Index>(p.points.size()), kn)};
  p.solution = solve_static_contact(k.stiffness, dofs, p.points, penalty, gap, {},
                                    std::vector<char>(p.points.size(), 1));
  return p;
}

// Uniaxial stress: rollers on the bottom of A, the top of B and the symmetry planes x = 0, y = 0,
// so the blocks and the penalty layer are three springs in series for any Poisson ratio.
void add_rollers(Model& m) {
  m.constraints = {{"a_bottom", {2}, 0.0}, {"b_top", {2}, 0.0}, {"x0", {0}, 0.0}, {"y0", {1}, 0.0}};
}

class ContactPatch : public ::testing::TestWithParam<ElementType> {};

TEST_P(ContactPatch, InterferenceGivesTheSeriesSpringForceAndAUniformPressure) {
  const double a = 0.02, la = 0.03, lb = 0.01, delta = 1e-5;
  Model m = two_blocks(GetParam(), a, la, lb, 2, 0.3);
  add_rollers(m);
  for (double kn : {1e12, 1e14, 1e17}) {
    const auto n_points = static_cast<Eigen::Index>(contact_points(m.mesh, m.contact_pairs).size());
    const Pressed p = press(m, kn, Eigen::VectorXd::Constant(n_points, -delta));
    const double area = a * a;
    const double force = delta / (la / (kYoungs * area) + lb / (kYoungs * area) + 1 / (kn * area));
    double resultant = 0.0;
    for (size_t k = 0; k < p.points.size(); ++k) {
      EXPECT_TRUE(p.solution.closed[k]);
      EXPECT_NEAR(p.solution.pressure[static_cast<Eigen::Index>(k)], force / area, 1e-9 * force / area);
      EXPECT_NEAR(p.solution.shear[static_cast<Eigen::Index>(k)], 0.0, 1e-6 * force / area);
      resultant += p.solution.pressure[static_cast<Eigen::Index>(k)] * p.points[k].area;
    }
    EXPECT_NEAR(resultant, force, 1e-9 * force) << "kn = " << kn;
    EXPECT_EQ(p.solution.iterations, 1);
    // The penetration is the force over the penalty layer's stiffness.
    EXPECT_NEAR(-p.solution.gap[0], force / (kn * area), 1e-9 * force / (kn * area));
  }
  // The stiff limit: the elastic solution of the two blocks.
  const auto n_points = static_cast<Eigen::Index>(contact_points(m.mesh, m.contact_pairs).size());
  const Pressed stiff = press(m, 1e20, Eigen::VectorXd::Constant(n_points, -delta));
  EXPECT_NEAR(stiff.solution.pressure[0], delta * kYoungs / (la + lb), 1e-5 * delta * kYoungs / (la + lb));
}

INSTANTIATE_TEST_SUITE_P(Elements, ContactPatch, ::testing::Values(ElementType::hex8, ElementType::hex20),
                         [](const auto& test_info) { return std::string(element_name(test_info.param)); });

// The stiffening law: its pressure is the energy's derivative and its tangent the pressure's, it starts
// with the penalty's slope, and two blocks pressed by a deep interference settle where the law and
// the blocks' series spring balance, p = kn s (exp(d / s) - 1) = E (delta - d) / (la + lb).
TEST(StaticContact, TheRoughLawIsConsistentAndTheBlocksSettleOnItsClosedForm) {
  const double kn = 3e13, sigma = 1e-6;
  for (double g : {2e-6, 0.0, -1e-6, -8e-6}) {
    const double h = 1e-10;
    EXPECT_NEAR(normal_pressure(kn, sigma, g),
                -(normal_energy(kn, sigma, g + h) - normal_energy(kn, sigma, g - h)) / (2 * h),
                1e-6 * std::max(kn * sigma, std::abs(normal_pressure(kn, sigma, g))));
    EXPECT_NEAR(normal_tangent(kn, sigma, g),
                -(normal_pressure(kn, sigma, g + h) - normal_pressure(kn, sigma, g - h)) / (2 * h),
                1e-5 * normal_tangent(kn, sigma, g));
  }
  EXPECT_DOUBLE_EQ(normal_tangent(kn, sigma, 0.0), kn);
  EXPECT_DOUBLE_EQ(normal_pressure(kn, 0.0, -1e-6), kn * 1e-6);  // sigma = 0: linear
  const double a = 0.02, la = 0.03, lb = 0.01, delta = 5e-5;
  Model m = two_blocks(ElementType::hex8, a, la, lb, 2, 0.3);
  add_rollers(m);
  const DofMap dofs = number_dofs(m);
  const GlobalMatrices k = assemble(m.mesh, m.section, {.stiffness = true, .mass = false});
  const std::vector<ContactPoint> points = contact_points(m.mesh, m.contact_pairs);
  const auto n = static_cast<Eigen::Index>(points.size());
  ContactPenalty rough{Eigen::VectorXd::Constant(n, kn), Eigen::VectorXd::Constant(n, kn), sigma};
  const StaticContactSolution s = solve_static_contact(k.stiffness, dofs, points, rough, Eigen::VectorXd::Constant(n, -delta),
                                                       {}, std::vector<char>(points.size(), 1));
  double lo = 0, hi = delta;  // penetration d
  for (int i = 0; i < 200; ++i) {
    const double d = 0.5 * (lo + hi);
    (kn * sigma * std::expm1(d / sigma) > kYoungs * (delta - d) / (la + lb) ? hi : lo) = d;
  }
  const double p = kYoungs * (delta - lo) / (la + lb);
  for (Eigen::Index i = 0; i < n; ++i) EXPECT_NEAR(s.pressure[i], p, 1e-8 * p);
  EXPECT_GT(s.newton_iterations, 1);
  EXPECT_NEAR(s.normal_stiffness[0], kn + p / sigma, 1e-6 * (kn + p / sigma));
}

TEST(StaticContact, AnInitialGapStaysOpenAndATiltedOneClosesPartOfTheInterface) {
  const double a = 0.02, la = 0.02, lb = 0.02;
  Model m = two_blocks(ElementType::hex8, a, la, lb, 6, 0.3);
  m.constraints = {{"a_bottom", {0, 1, 2}, 0.0}, {"b_top", {0, 1, 2}, 0.0}};
  const std::vector<ContactPoint> points = contact_points(m.mesh, m.contact_pairs);
  const auto n = static_cast<Eigen::Index>(points.size());
  const Pressed open = press(m, 1e14, Eigen::VectorXd::Constant(n, 1e-6));
  for (size_t k = 0; k < points.size(); ++k) EXPECT_FALSE(open.solution.closed[k]);
  EXPECT_NEAR(open.solution.displacement.cwiseAbs().maxCoeff(), 0.0, 1e-18);
  // Overlap on x < a / 2, a gap beyond: the status must settle with both kinds and complementarity.
  Eigen::VectorXd tilted(n);
  for (Eigen::Index k = 0; k < n; ++k) tilted[k] = 1e-5 * (points[static_cast<size_t>(k)].position.x() / a - 0.5);
  const Pressed part = press(m, 1e14, tilted);
  int closed = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const bool c = part.solution.closed[static_cast<size_t>(k)];
    closed += c;
    if (c) {
      EXPECT_LE(part.solution.gap[k], 1e-9 * 1e-5) << "a closed point must not pull";
    } else {
      EXPECT_GE(part.solution.gap[k], -1e-9 * 1e-5) << "an open point must not penetrate";
    }
  }
  EXPECT_GT(closed, 0);
  EXPECT_LT(closed, n);
  EXPECT_GT(part.solution.iterations, 1);
  EXPECT_GT(part.solution.status_changes, 0);
}

TEST(StaticContact, AStatusThatDoesNotSettleIsASolverErrorNamingTheStepAndTheChanges) {
  Model m = two_blocks(ElementType::hex8, 0.02, 0.02, 0.02, 6, 0.3);
  m.constraints = {{"a_bottom", {0, 1, 2}, 0.0}, {"b_top", {0, 1, 2}, 0.0}};
  const DofMap dofs = number_dofs(m);
  const GlobalMatrices k = assemble(m.mesh, m.section, {.stiffness = true, .mass = false});
  const std::vector<ContactPoint> points = contact_points(m.mesh, m.contact_pairs);
  const auto n = static_cast<Eigen::Index>(points.size());
  Eigen::VectorXd tilted(n);
  for (Eigen::Index i = 0; i < n; ++i) tilted[i] = 1e-5 * (points[static_cast<size_t>(i)].position.x() / 0.02 - 0.5);
  ContactPenalty penalty{Eigen::VectorXd::Constant(n, 1e14), Eigen::VectorXd::Constant(n, 1e14)};
  try {
    solve_static_contact(k.stiffness, dofs, points, penalty, tilted, {}, std::vector<char>(points.size(), 1),
                         {.max_iterations = 1}, "test");
    ADD_FAILURE() << "expected SolverError";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("load step 1 of 1"), std::string::npos) << what;
    EXPECT_NE(what.find("status changes"), std::string::npos) << what;
  }
}

TEST(StaticContact, ABodyHeldOnlyByFrictionlessContactIsASolverError) {
  Model m = two_blocks(ElementType::hex8, 0.02, 0.02, 0.02, 2, 0.3);
  m.constraints = {{"a_bottom", {0, 1, 2}, 0.0}};  // B is held by the contact alone
  const DofMap dofs = number_dofs(m);
  const GlobalMatrices k = assemble(m.mesh, m.section, {.stiffness = true, .mass = false});
  const std::vector<ContactPoint> points = contact_points(m.mesh, m.contact_pairs);
  const auto n = static_cast<Eigen::Index>(points.size());
  ContactPenalty frictionless{Eigen::VectorXd::Constant(n, 1e14), Eigen::VectorXd::Zero(n)};
  EXPECT_THROW(solve_static_contact(k.stiffness, dofs, points, frictionless, Eigen::VectorXd::Constant(n, -1e-6), {},
                                    std::vector<char>(points.size(), 1)),
               SolverError);
}

// A bar (length L along z, lateral motion held, nu = 0: exactly one-dimensional) clamped at z = 0
// and touching at z = L a block that is clamped everywhere: the penalty layer is a spring K = kn A
// to the ground. Axial modes: tan(x) = -x / kappa, x = beta L, kappa = K L / (E A); glued: x = pi.
TEST(ContactModal, BarOnThePenaltySpringHasTheFixedSpringBarFrequencies) {
  const double a = 0.01, length = 0.5, kappa = 1.0;
  Model m;
  m.section = {.youngs_modulus = kYoungs, .poisson_ratio = 0.0, .density = 7800.0};
  {
    std::vector<std::vector<int>> origin;
    m.mesh = concatenate_meshes({generate_hex_block(box(a, a, 0, length, 1, 1, 24, ElementType::hex20)),
                                 generate_hex_block(box(a, a, length, length + 0.01, 1, 1, 1, ElementType::hex20))},
                                &origin);
    m.node_sets.clear();
    for (int node : origin[0]) {
      m.node_sets["bar"].push_back(node);
      if (std::abs(m.mesh.coords(node, 2)) < 1e-12) m.node_sets["bar_root"].push_back(node);
      if (std::abs(m.mesh.coords(node, 2) - length) < 1e-12) m.node_sets["bar_end"].push_back(node);
    }
    for (int node : origin[1]) {
      m.node_sets["block"].push_back(node);
      if (std::abs(m.mesh.coords(node, 2) - length) < 1e-12) m.node_sets["block_face"].push_back(node);
    }
    m.contact_pairs = {build_contact_pair(
        m, {.name = "end", .contact = "bar_end", .target = "block_face", .interference = false, .at = {}})};
  }
  m.constraints = {{"bar", {0, 1}, 0.0}, {"bar_root", {2}, 0.0}, {"block", {0, 1, 2}, 0.0}};
  const double h = contact_points(m.mesh, m.contact_pairs).front().facet_size;  // = a
  ContactModalSpec spec;
  spec.modes = 2;
  spec.interferences = {0.0};
  // kn = FKN E / h and K = kn a^2 = kappa E a^2 / L: FKN = kappa h / L.
  spec.penalty_factors = {kappa * h / length};
  const ContactModalOutcome o = run_contact_modal(m, spec);
  const double c = std::sqrt(kYoungs / 7800.0);
  // Roots of tan(x) = -x / kappa on (pi/2, pi) and (3 pi/2, 2 pi), by bisection.
  auto root = [&](double lo, double hi) {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (std::tan(mid) + mid / kappa > 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const double x1 = root(std::numbers::pi / 2 + 1e-9, std::numbers::pi), x2 = root(1.5 * std::numbers::pi + 1e-9, 2 * std::numbers::pi);
  ASSERT_EQ(o.grid.size(), 1u);
  EXPECT_NEAR(o.grid[0].frequencies_hz[0], x1 * c / (2 * std::numbers::pi * length), 2e-5 * x1 * c / length);
  EXPECT_NEAR(o.grid[0].frequencies_hz[1], x2 * c / (2 * std::numbers::pi * length), 2e-4 * x2 * c / length);
  // Glued (tied): a fixed-fixed bar, f = k c / (2 L).
  ASSERT_EQ(o.glued_hz.size(), 2);
  EXPECT_NEAR(o.glued_hz[0], c / (2 * length), 2e-5 * c / length);
  EXPECT_NEAR(o.glued_hz[1], c / length, 2e-4 * c / length);
  EXPECT_LT(o.grid[0].frequencies_hz[0], o.glued_hz[0]);
}

TEST(ContactPairs, GluedNodesAndNonConformingFacesAreRefused) {
  Model m = two_blocks(ElementType::hex8, 0.02, 0.02, 0.02, 2, 0.3);
  m.node_sets["both"] = m.node_sets["a_top"];
  m.node_sets["both"].insert(m.node_sets["both"].end(), m.node_sets["b_bottom"].begin(), m.node_sets["b_bottom"].end());
  std::sort(m.node_sets["both"].begin(), m.node_sets["both"].end());
  EXPECT_THROW(build_contact_pair(m, {.name = "p", .contact = "a_top", .target = "both", .interference = false, .at = {}}),
               InputError);
  EXPECT_THROW(build_contact_pair(m, {.name = "p", .contact = "a_top", .target = "b_top", .interference = false, .at = {}}),
               InputError);
  EXPECT_THROW(build_contact_pair(m, {.name = "p", .contact = "a_top", .target = "nothing", .interference = false, .at = {}}),
               InputError);
}

// Through the command line's pipeline: a body held by frictionless contact alone fails the run with
// exit 3 and the load step, and writes no result table.
class ContactCase : public test::TempFolderTest {};

// Two hex8 blocks (bodies "lower" and "upper") clamped at their far ends, pressed by 1e-6 m.
const char* const kTwoBlocksCase = R"([case]
name = "two_blocks_contact"
title = "Two blocks pressed together"

[material]
E = 2.0e11
nu = 0.3
rho = 7800.0

[mesh]
kind = "hex_blocks"
element = "hex8"

[[mesh.block]]
body = "lower"
corners = [[0, 0, 0], [0.02, 0, 0], [0.02, 0.02, 0], [0, 0.02, 0], [0, 0, 0.02], [0.02, 0, 0.02], [0.02, 0.02, 0.02], [0, 0.02, 0.02]]
nx = 4
ny = 4
nz = 2

[[mesh.block]]
body = "upper"
corners = [[0, 0, 0.02], [0.02, 0, 0.02], [0.02, 0.02, 0.02], [0, 0.02, 0.02], [0, 0, 0.04], [0.02, 0, 0.04], [0.02, 0.02, 0.04], [0, 0.02, 0.04]]
nx = 4
ny = 4
nz = 2

[sets.bottom]
z = 0.0

[sets.top]
z = 0.04

[sets.lower_face]
body = "lower"
z = 0.02

[sets.upper_face]
body = "upper"
z = 0.02

[[bc]]
set = "bottom"
dofs = ["x", "y", "z"]

[[bc]]
set = "top"
dofs = ["x", "y", "z"]

[[contact]]
name = "interface"
contact = "lower_face"
target = "upper_face"
interference = true

[analysis]
type = "contact_modal"
modes = 4
interference_m = [1e-6]
penalty_factor = [1.0]
)";

TEST_F(ContactCase, AFrictionlessFreeBodyFailsTheRunAsASolverFailure) {
  std::string text = kTwoBlocksCase;
  // The upper block loses its clamp and its tangential contact.
  text.replace(text.find("[[bc]]\nset = \"top\""), std::string("[[bc]]\nset = \"top\"\ndofs = [\"x\", \"y\", \"z\"]").size(), "");
  text += "tangential = \"frictionless\"\n";
  const RunOutcome o = run_case(write(text), {.out_dir = dir_ / "out", .study = false, .plots = false});
  EXPECT_EQ(o.record.status, RunStatus::solver_failed) << o.record.message;
  EXPECT_EQ(exit_code(o.record.status), exit_solver_failed);
  EXPECT_NE(o.record.message.find("load step"), std::string::npos) << o.record.message;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "frequencies_grid.csv"));
}

TEST_F(ContactCase, TwoBodiesOfHexBlocksPressedTogetherRunThroughTheCommandLinePipeline) {
  const RunOutcome o = run_case(write(kTwoBlocksCase), {.out_dir = dir_ / "out", .study = false, .plots = false});
  EXPECT_EQ(o.record.status, RunStatus::no_checks) << o.record.message;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / "frequencies_grid.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / "contact_state.csv"));
}

}  // namespace
}  // namespace bb
