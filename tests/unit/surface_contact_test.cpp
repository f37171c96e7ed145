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

namespace bb {
namespace {

constexpr double kE = 2.0e11;

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
  m.section = {.youngs_modulus = kE, .poisson_ratio = nu, .density = 7800.0};
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
    const double force = delta / (la / (kE * area) + lb / (kE * area) + 1 / (kn * area));
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
  EXPECT_NEAR(stiff.solution.pressure[0], delta * kE / (la + lb), 1e-5 * delta * kE / (la + lb));
}

INSTANTIATE_TEST_SUITE_P(Elements, ContactPatch, ::testing::Values(ElementType::hex8, ElementType::hex20),
                         [](const auto& info) { return std::string(element_name(info.param)); });

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
  m.section = {.youngs_modulus = kE, .poisson_ratio = 0.0, .density = 7800.0};
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
  const double c = std::sqrt(kE / 7800.0);
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

}  // namespace
}  // namespace bb
