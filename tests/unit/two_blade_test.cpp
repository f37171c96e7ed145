// The two-blade test article (articles/two_blade) and its case-format integration: the merged
// mesh is one conforming body glued only where the thesis glues it, it fills exactly the volume
// of the bodies, the named points are nodes, impossible geometry is rejected by name, and the two
// identical blades give near-degenerate pairs of modes. Units: SI.
#include "articles/two_blade.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "analysis/modal_analysis.hpp"
#include "analysis/mode_pairs.hpp"
#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "fe/solid.hpp"
#include "mesh/hex_block.hpp"
#include "model/build_model.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

constexpr double kTol = 1e-9;

struct Merged {
  TwoBladeArticle article;
  Mesh mesh;
  std::vector<std::vector<int>> origin;  // per block, the merged index of each of its nodes
};

Merged merged_article(const TwoBladeDimensions& d, ElementType element) {
  Merged m;
  m.article = two_blade_article(d, element);
  std::vector<Mesh> parts;
  for (const HexBlockSpec& b : m.article.blocks) parts.push_back(generate_hex_block(b));
  m.mesh = merge_meshes(parts, 1e-7, &m.origin);
  return m;
}

// Bodies each merged node belongs to.
std::vector<std::set<TwoBladeBody>> bodies_of_nodes(const Merged& m) {
  std::vector<std::set<TwoBladeBody>> bodies(static_cast<size_t>(m.mesh.n_nodes()));
  for (size_t b = 0; b < m.origin.size(); ++b)
    for (int n : m.origin[b]) bodies[static_cast<size_t>(n)].insert(m.article.body[b]);
  return bodies;
}

// Dimensions away from every default, so that no test passes by a coincidence of the nominal
// values: tapered airfoil, steeper and narrower platform, wider neck.
TwoBladeDimensions unusual_dimensions() {
  TwoBladeDimensions d;
  d.w_n = 0.012;
  d.H_n = 0.022;
  d.B_p = 0.032;
  d.beta_deg = 55.0;
  d.e_p = 0.011;
  d.w = 0.007;
  d.w_t = 0.004;
  d.L_a = 0.12;
  d.p = 0.056;
  return d;
}

// Hex8 faces by corner (0-based), ordered so that the right-hand normal points out of the element.
constexpr std::array<std::array<int, 4>, 6> kFaces = {{
    {0, 3, 2, 1},
    {4, 5, 6, 7},
    {0, 1, 5, 4},
    {1, 2, 6, 5},
    {2, 3, 7, 6},
    {3, 0, 4, 7},
}};

bool inside_convex_quad(const std::array<Vec2, 4>& q, const Vec2& p) {
  for (size_t a = 0; a < 4; ++a) {
    const Vec2 e = q[(a + 1) % 4] - q[a], r = p - q[a];
    if (e.x() * r.y() - e.y() * r.x() < -1e-15) return false;
  }
  return true;
}

TEST(TwoBladeMesh, IsOneConnectedBodyOfConformingElements) {
  for (ElementType element : {ElementType::hex8, ElementType::hex20}) {
    SCOPED_TRACE(std::string(element_name(element)));
    const TwoBladeDimensions d = unusual_dimensions();
    const Merged m = merged_article(d, element);
    const ElementBlock& block = m.mesh.blocks.at(0);
    ASSERT_EQ(m.mesh.blocks.size(), 1u);

    // One connected component through shared nodes.
    std::vector<int> parent(static_cast<size_t>(m.mesh.n_nodes()));
    std::iota(parent.begin(), parent.end(), 0);
    std::function<int(int)> root = [&](int a) { return parent[a] == a ? a : parent[a] = root(parent[a]); };
    for (Eigen::Index e = 0; e < block.conn.rows(); ++e)
      for (Eigen::Index a = 1; a < block.conn.cols(); ++a) parent[root(block.conn(e, a))] = root(block.conn(e, 0));
    std::set<int> components;
    for (int n = 0; n < m.mesh.n_nodes(); ++n) components.insert(root(n));
    EXPECT_EQ(components.size(), 1u);

    // Conforming: a face is shared by at most two elements, and a face that only one element
    // has lies on the surface of the article: on z = 0 or z = t, or with empty space (no block of
    // the planar decomposition) just outside it. A mismatch of divisions on a glued interface
    // would leave unshared faces inside the solid.
    std::map<std::array<int, 4>, int> count;
    std::map<std::array<int, 4>, std::pair<Eigen::Index, int>> owner;
    for (Eigen::Index e = 0; e < block.conn.rows(); ++e)
      for (int f = 0; f < 6; ++f) {
        std::array<int, 4> key;
        for (size_t a = 0; a < 4; ++a) key[a] = block.conn(e, kFaces[static_cast<size_t>(f)][a]);
        std::sort(key.begin(), key.end());
        ++count[key];
        owner[key] = {e, f};
      }
    std::vector<std::array<Vec2, 4>> footprint;
    for (const HexBlockSpec& b : m.article.blocks)
      footprint.push_back(
          {b.corners[0].head<2>(), b.corners[1].head<2>(), b.corners[2].head<2>(), b.corners[3].head<2>()});
    int surface = 0;
    for (const auto& [key, n] : count) {
      ASSERT_LE(n, 2);
      if (n == 2) continue;
      ++surface;
      const auto [e, f] = owner[key];
      std::array<Vec3, 4> x;
      for (size_t a = 0; a < 4; ++a)
        x[a] = m.mesh.coords.row(block.conn(e, kFaces[static_cast<size_t>(f)][a])).transpose();
      const Vec3 centre = 0.25 * (x[0] + x[1] + x[2] + x[3]);
      const Vec3 normal = (x[2] - x[0]).cross(x[3] - x[1]).normalized();
      if (std::abs(normal.z()) > 0.5) {
        EXPECT_TRUE(std::abs(centre.z()) < kTol || std::abs(centre.z() - d.t) < kTol) << centre.transpose();
        continue;
      }
      const Vec2 outside = centre.head<2>() + 1e-6 * normal.head<2>().normalized();
      for (const auto& quad : footprint)
        ASSERT_FALSE(inside_convex_quad(quad, outside)) << "unshared face inside the solid at " << centre.transpose();
    }
    EXPECT_GT(surface, 0);
  }
}

TEST(TwoBladeMesh, NeckIsNotGluedToTheArmsOnlyRootShouldersWedgesAndFloorAre) {
  TwoBladeDimensions d;
  for (ElementType element : {ElementType::hex8, ElementType::hex20}) {
    SCOPED_TRACE(std::string(element_name(element)));
    const Merged m = merged_article(d, element);
    const auto bodies = bodies_of_nodes(m);
    const auto& Y = m.article.levels;
    // Nodes on a face of nx x nz divisions: corners, plus the mid-edge nodes of hex20.
    const int nz = d.nz();
    auto face_nodes = [&](int nx) {
      return element == ElementType::hex20 ? (2 * nx + 1) * (2 * nz + 1) - nx * nz : (nx + 1) * (nz + 1);
    };
    std::map<std::pair<TwoBladeBody, TwoBladeBody>, int> shared;
    for (int n = 0; n < m.mesh.n_nodes(); ++n) {
      const auto& s = bodies[static_cast<size_t>(n)];
      ASSERT_LE(s.size(), 2u) << "node " << n;
      if (s.size() < 2) continue;
      const TwoBladeBody a = *s.begin(), b = *s.rbegin();
      ++shared[{a, b}];
      const double x = m.mesh.coords(n, 0), y = m.mesh.coords(n, 1);
      const double o = (a == TwoBladeBody::blade2 || a == TwoBladeBody::wedge2) ? d.p : 0.0;
      if (b == TwoBladeBody::fixture && (a == TwoBladeBody::blade1 || a == TwoBladeBody::blade2)) {
        // Only the root shoulders, on the arms' underside; never the neck in the slot.
        EXPECT_NEAR(y, Y[3], kTol);
        const bool left = x >= o - kTol && x <= o + d.x_n0() - d.g_s + kTol;
        const bool right = x >= o + d.x_n1 + d.g_s - kTol && x <= o + d.B_r + kTol;
        EXPECT_TRUE(left || right) << "blade node glued to the fixture at x = " << x;
      } else if (b == TwoBladeBody::fixture) {
        EXPECT_NEAR(y, Y[1], kTol);  // wedge on the cavity floor
      } else {
        EXPECT_NEAR(y, Y[2], kTol);  // root on its wedge
      }
    }
    using B = TwoBladeBody;
    EXPECT_EQ(shared.size(), 6u);  // each blade with its wedge and the fixture, each wedge with the fixture
    for (auto [blade, wedge] : {std::pair{B::blade1, B::wedge1}, std::pair{B::blade2, B::wedge2}}) {
      EXPECT_EQ((shared[{blade, B::fixture}]), 2 * face_nodes(1));  // two shoulders of one division
      EXPECT_EQ((shared[{blade, wedge}]), face_nodes(6));           // root bottom, 1 + 1 + 2 + 1 + 1 divisions
      EXPECT_EQ((shared[{wedge, B::fixture}]), face_nodes(6));
    }
    // Nothing at all inside the slot clearance, and the neck faces inside the slot are blade only.
    for (int n = 0; n < m.mesh.n_nodes(); ++n) {
      const double x = m.mesh.coords(n, 0), y = m.mesh.coords(n, 1);
      if (y <= Y[3] + kTol || y >= Y[4] - kTol) continue;
      EXPECT_FALSE(x > d.x_n0() - d.g_s + kTol && x < d.x_n0() - kTol) << "node inside the slot clearance";
      if (std::abs(x - d.x_n0()) < kTol) {
        EXPECT_EQ(bodies[static_cast<size_t>(n)], std::set<TwoBladeBody>{B::blade1});
      }
    }
  }
}

double element_volume(const Mesh& mesh, const ElementBlock& b, Eigen::Index e) {
  if (b.type == ElementType::hex20) {
    fe::Hex20Coords x;
    for (int a = 0; a < 20; ++a) x.row(a) = mesh.coords.row(b.conn(e, a));
    return fe::hex20_volume(x);
  }
  fe::Hex8Coords x;
  for (int a = 0; a < 8; ++a) x.row(a) = mesh.coords.row(b.conn(e, a));
  return fe::hex8_volume(x);
}

TEST(TwoBladeMesh, FillsTheAnalyticVolumeOfEachBody) {
  const TwoBladeDimensions d = unusual_dimensions();
  for (ElementType element : {ElementType::hex8, ElementType::hex20}) {
    SCOPED_TRACE(std::string(element_name(element)));
    const TwoBladeArticle a = two_blade_article(d, element);
    std::map<TwoBladeBody, double> volume;
    for (size_t k = 0; k < a.blocks.size(); ++k) {
      const Mesh part = generate_hex_block(a.blocks[k]);
      for (Eigen::Index e = 0; e < part.blocks[0].conn.rows(); ++e)
        volume[a.body[k]] += element_volume(part, part.blocks[0], e);
    }
    // Cross-sections (the article is an extrusion over t), written from the dimensions alone.
    const double c = 0.5 * (d.B_p - d.w_n) * std::tan(d.beta_deg * std::numbers::pi / 180.0);
    const double blade =
        d.B_r * d.H_r + d.w_n * d.H_n + 0.5 * (d.B_p + d.w_n) * c + d.B_p * d.e_p + 0.5 * (d.w + d.w_t) * d.L_a;
    const double wedge = d.B_r * d.h_w;
    const double width = (d.p + d.B_r + 2 * (d.g_r + d.m_f)), height = d.t_fb + d.h_w + d.H_r + d.t_a;
    const double fixture = width * height - 2 * ((d.B_r + 2 * d.g_r) * (d.h_w + d.H_r) + (d.w_n + 2 * d.g_s) * d.t_a);
    for (auto [body, area] : {std::pair{TwoBladeBody::blade1, blade}, std::pair{TwoBladeBody::blade2, blade},
                              std::pair{TwoBladeBody::wedge1, wedge}, std::pair{TwoBladeBody::wedge2, wedge},
                              std::pair{TwoBladeBody::fixture, fixture}})
      EXPECT_NEAR(volume[body], area * d.t, 1e-12 * area * d.t) << static_cast<int>(body);
  }
}

// A modal case on the article, parsed from TOML as a user would write it.
std::string article_case(const std::string& mesh_lines, const std::string& extra = "") {
  return R"(
[case]
name = "two_blade_unit"
[material]
E = 2.2e11
nu = 0.33
rho = 7730.0
[mesh]
kind = "two_blade"
)" + mesh_lines +
         R"(
[[bc]]
set = "fixture_base"
dofs = ["x", "y", "z"]
[[bc]]
set = "fixture_left"
dofs = ["x", "y", "z"]
[[bc]]
set = "fixture_right"
dofs = ["x", "y", "z"]
[analysis]
type = "modal"
modes = 4
[analysis.pairs]
left = "T1"
right = "T2"
direction = "x"
left_tip = "tip1"
right_tip = "tip2"
)" + extra;
}

class TwoBladeCase : public test::TempFolderTest {
 protected:
  std::string error_of(const std::string& text) {
    try {
      build_model(parse_case_file(write(text)).model);
    } catch (const InputError& e) {
      return e.what();
    }
    return {};
  }
};

TEST_F(TwoBladeCase, AutomaticNodeSetsSitAtTheNamedPointsAndFaces) {
  const CaseSpec spec = parse_case_file(write(article_case("element = \"hex8\"\n")));
  const Model model = build_model(spec.model);
  const TwoBladeDimensions d;  // nominal: the points of the reconstruction, worked out by hand
  const std::map<std::string, Vec3> expected = {
      {"T1", {0.0175, 0.2200, 0.025}},     {"T2", {0.0675, 0.2200, 0.025}},     {"F", {0.0702, 0.102625, 0.025}},
      {"L1", {0.025625, 0.034125, 0.025}}, {"L2", {0.031875, 0.040375, 0.025}}, {"R", {0.05625, 0.03725, 0.025}},
  };
  for (const auto& [name, x] : expected) {
    ASSERT_TRUE(model.node_sets.count(name)) << name;
    ASSERT_EQ(model.node_sets.at(name).size(), 1u) << name;
    const Vec3 node = model.mesh.coords.row(model.node_sets.at(name)[0]).transpose();
    EXPECT_LT((node - x).norm(), 1e-12) << name << " at " << node.transpose();
  }
  // Faces, hex8 at refinement 1 (4 divisions through t, 5 node layers): the base spans 22 x
  // divisions; each lateral face 2 + 3 + 1 along y; each tip face 2 across the airfoil.
  auto all_on = [&](const std::string& set, int axis, double value) {
    for (int n : model.node_sets.at(set)) EXPECT_NEAR(model.mesh.coords(n, axis), value, kTol) << set;
    return model.node_sets.at(set).size();
  };
  EXPECT_EQ(all_on("fixture_base", 1, -0.030), 23u * 5u);
  EXPECT_EQ(all_on("fixture_left", 0, -0.0175), 7u * 5u);
  EXPECT_EQ(all_on("fixture_right", 0, 0.1025), 7u * 5u);
  EXPECT_EQ(all_on("tip1", 1, 0.22), 3u * 5u);
  EXPECT_EQ(all_on("tip2", 1, 0.22), 3u * 5u);
  for (int n : model.node_sets.at("tip2")) EXPECT_NEAR(model.mesh.coords(n, 0), 0.0675, 0.5 * d.w + kTol);
}

TEST_F(TwoBladeCase, IdenticalBladesGiveNearDegeneratePairsInPhaseAndOutOfPhase) {
  const CaseSpec spec = parse_case_file(write(article_case("element = \"hex8i\"\nrefinement = 1\n")));
  const Model model = build_model(spec.model);
  const ModalResult modal =
      solve_modal(model, std::get<ModalSpec>(spec.analysis).modes, std::get<ModalSpec>(spec.analysis).options);
  ASSERT_EQ(modal.frequencies_hz.size(), 4);
  const Eigen::VectorXd& f = modal.frequencies_hz;
  EXPECT_LT(f[1] / f[0] - 1.0, 0.01);  // first flexure of the two blades
  EXPECT_LT(f[3] / f[2] - 1.0, 0.01);  // second flexure
  EXPECT_GT(f[2] / f[1], 2.0);         // and two distinct pairs
  const std::vector<ModeLabel> labels = label_mode_pairs(model, modal, *std::get<ModalSpec>(spec.analysis).pairs);
  ASSERT_EQ(labels.size(), 4u);
  for (int pair = 0; pair < 2; ++pair) {
    const std::set<std::string> phases = {labels[2 * pair].pair, labels[2 * pair + 1].pair};
    EXPECT_EQ(phases, (std::set<std::string>{"IP", "OOP"})) << "pair " << pair;
    EXPECT_EQ(labels[2 * pair].type, "flexure-x");
    EXPECT_EQ(labels[2 * pair + 1].type, "flexure-x");
  }
}

TEST(TwoBladeDimensions, ValidateNamesTheDimensionThatMakesTheGeometryImpossible) {
  auto offender = [](const std::function<void(TwoBladeDimensions&)>& change) {
    TwoBladeDimensions d;
    change(d);
    try {
      d.validate();
    } catch (const DimensionError& e) {
      return e.name();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(offender([](auto&) {}), "(accepted)");
  EXPECT_EQ(offender([](auto& d) { d.H_n = d.t_a; }), "H_n");      // platform inside the arms
  EXPECT_EQ(offender([](auto& d) { d.w = d.B_p + 0.001; }), "w");  // airfoil wider than the platform
  EXPECT_EQ(offender([](auto& d) { d.p = d.B_p; }), "p");          // platforms overlap
  EXPECT_EQ(offender([](auto& d) { d.p = 0.04; }), "p");           // no wall between the cavities
  EXPECT_EQ(offender([](auto& d) { d.B_p = d.w_n; }), "B_p");
  EXPECT_EQ(offender([](auto& d) { d.L_a = -0.1; }), "L_a");
  EXPECT_EQ(offender([](auto& d) { d.t = 0.0; }), "t");
  EXPECT_EQ(offender([](auto& d) { d.m_f = NAN; }), "m_f");
  EXPECT_EQ(offender([](auto& d) { d.g_s = 1e-8; }), "g_s");     // would close when merging
  EXPECT_EQ(offender([](auto& d) { d.x_n1 = 0.033; }), "x_n1");  // no right shoulder
  EXPECT_EQ(offender([](auto& d) { d.w_n = 0.02; }), "w_n");     // no left shoulder
  EXPECT_EQ(offender([](auto& d) { d.beta_deg = 90.0; }), "beta_deg");
  EXPECT_EQ(offender([](auto& d) { d.w_t = -0.001; }), "w_t");
  EXPECT_EQ(offender([](auto& d) { d.airfoil_divisions = 7; }), "airfoil_divisions");  // F off the nodes
  EXPECT_EQ(offender([](auto& d) { d.thickness_divisions = 3; }), "thickness_divisions");
  EXPECT_EQ(offender([](auto& d) { d.refinement = 0; }), "refinement");
  EXPECT_THROW(two_blade_article(
                   [] {
                     TwoBladeDimensions d;
                     d.H_n = 0.005;
                     return d;
                   }(),
                   ElementType::hex20),
               InputError);
}

TEST_F(TwoBladeCase, DimensionsTableSetsAnySubsetAndRejectsUnknownNamesAndImpossibleValues) {
  const CaseSpec spec = parse_case_file(
      write(article_case("element = \"hex20\"\nrefinement = 3\n[mesh.dimensions]\nL_a = 0.15\nw = 0.006\n")));
  ASSERT_EQ(spec.model.mesh.kind, MeshSpec::Kind::two_blade);
  EXPECT_EQ(spec.model.mesh.two_blade.L_a, 0.15);
  EXPECT_EQ(spec.model.mesh.two_blade.w, 0.006);
  EXPECT_EQ(spec.model.mesh.two_blade.H_n, TwoBladeDimensions{}.H_n);
  EXPECT_EQ(spec.model.mesh.two_blade.refinement, 3);
  EXPECT_EQ(spec.model.mesh.element, ElementType::hex20);

  const std::string typo = error_of(article_case("element = \"hex20\"\n[mesh.dimensions]\nL_b = 0.15\n"));
  EXPECT_NE(typo.find("mesh.dimensions.L_b"), std::string::npos) << typo;
  EXPECT_NE(typo.find("case.toml:"), std::string::npos) << typo;

  // The 12th line of the case sets H_n: the message points at it.
  const std::string impossible = error_of(article_case("element = \"hex20\"\n[mesh.dimensions]\nH_n = 0.004\n"));
  EXPECT_NE(impossible.find("case.toml:12: 'mesh.dimensions.H_n'"), std::string::npos) << impossible;

  const std::string reserved = error_of(article_case("element = \"hex8\"\n", "[sets.T1]\nids = [1]\n"));
  EXPECT_NE(reserved.find("'sets.T1'"), std::string::npos) << reserved;

  const std::string planar = error_of(article_case("element = \"q4\"\n"));
  EXPECT_NE(planar.find("solid element"), std::string::npos) << planar;
}

}  // namespace
}  // namespace bb
