// The chapter-2 blade meshes (articles/blade_section): the element and node counts the thesis states
// for its three discretizations, the Presams node numbering, the root's clamped nodes, and a
// geometry that is the two-blade article's blade (areas and volume).
#include "articles/blade_section.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "assembly/assemble.hpp"

namespace bb {
namespace {

int count(const Mesh& mesh, ElementType type) {
  int n = 0;
  for (const ElementBlock& b : mesh.blocks) n += b.type == type ? static_cast<int>(b.ids.size()) : 0;
  return n;
}

BladeSection thesis_mesh(ElementType element) {
  return blade_section(TwoBladeDimensions{}, blade_section_divisions(element), element);
}

// The blade's planar area: root, neck, platform (two 45-degree corners, the central part, the lip)
// and airfoil.
double outline_area(const TwoBladeDimensions& d, bool corners) {
  const double c = d.contact_rise();
  return d.B_r * d.H_r + d.w_n * d.H_n + d.w_n * c + (corners ? c * c : 0.0) + d.B_p * d.e_p + d.w * d.L_a;
}

double mass_of(const Mesh& mesh, double thickness) {
  const fe::PlaneSection section{2.2e11, 0.3, 1.0, thickness};
  const GlobalMatrices g = assemble(mesh, section, {.stiffness = false, .mass = true});
  return g.mass.sum() / mesh.dim;  // rigid translation: total mass per direction
}

TEST(BladeSection, Q4MeshHasTheThesisCounts166RectanglesTwoTrianglesAnd233Nodes) {
  const BladeSection b = thesis_mesh(ElementType::q4);
  EXPECT_EQ(count(b.mesh, ElementType::q4), 166);
  EXPECT_EQ(count(b.mesh, ElementType::cst), 2);
  EXPECT_EQ(b.mesh.n_nodes(), 233);
}

TEST(BladeSection, CstMeshHas112Triangles) {
  const BladeSection b = thesis_mesh(ElementType::cst);
  EXPECT_EQ(count(b.mesh, ElementType::cst), 112);
  EXPECT_EQ(count(b.mesh, ElementType::q4), 0);
}

TEST(BladeSection, Hex8MeshHas196ElementsFourThroughTheThickness) {
  const BladeSection b = thesis_mesh(ElementType::hex8);
  EXPECT_EQ(count(b.mesh, ElementType::hex8), 196);
  int levels = 0;
  for (int n = 0; n < b.mesh.n_nodes(); ++n) levels += b.mesh.coords(n, 0) == 0.0 && b.mesh.coords(n, 1) == 0.0 ? 1 : 0;
  EXPECT_EQ(levels, 5);  // the root corner node at z = 0, t/4, ..., t
}

TEST(BladeSection, PlaneNodesOneToFourAreThePresamsNodes) {
  const TwoBladeDimensions d;
  const BladeSection b = thesis_mesh(ElementType::q4);
  const double expected[4][2] = {{0.0, 0.0}, {d.B_r, 0.0}, {d.B_r, d.H_r}, {d.x_n1, d.H_r}};
  for (int i = 0; i < 4; ++i) {
    const int n = b.mesh.index_of(i + 1);
    EXPECT_DOUBLE_EQ(b.mesh.coords(n, 0), expected[i][0]) << "node " << i + 1;
    EXPECT_DOUBLE_EQ(b.mesh.coords(n, 1), expected[i][1]) << "node " << i + 1;
  }
  const auto& root = b.sets.at("root");
  for (int id : {1, 2, 3})
    EXPECT_NE(std::find(root.begin(), root.end(), b.mesh.index_of(id)), root.end()) << "node " << id;
  EXPECT_EQ(std::find(root.begin(), root.end(), b.mesh.index_of(4)), root.end()) << "node 4 is free (Fig. 2.19)";
}

TEST(BladeSection, MeshesCoverTheBladeOutline) {
  const TwoBladeDimensions d;
  EXPECT_NEAR(mass_of(thesis_mesh(ElementType::q4).mesh, d.t), outline_area(d, true) * d.t, 1e-12);
  EXPECT_NEAR(mass_of(thesis_mesh(ElementType::cst).mesh, d.t), outline_area(d, true) * d.t, 1e-12);
  EXPECT_NEAR(mass_of(thesis_mesh(ElementType::hex8).mesh, d.t), outline_area(d, false) * d.t, 1e-12);
}

TEST(BladeSection, TipAndMidAreSingleNodesOnTheAirfoilsTrailingFace) {
  const TwoBladeDimensions d;
  for (ElementType e : {ElementType::q4, ElementType::cst, ElementType::hex8}) {
    const BladeSection b = thesis_mesh(e);
    ASSERT_EQ(b.sets.at("tip").size(), 1u);
    ASSERT_EQ(b.sets.at("mid").size(), 1u);
    const int tip = b.sets.at("tip")[0], mid = b.sets.at("mid")[0];
    EXPECT_NEAR(b.mesh.coords(tip, 1), d.levels()[8], 1e-12);
    EXPECT_NEAR(b.mesh.coords(tip, 0), d.x_c() + 0.5 * d.w, 1e-12);
    EXPECT_NEAR(b.mesh.coords(mid, 1), 0.5 * (d.levels()[7] + d.levels()[8]),
                0.5 * d.L_a / blade_section_divisions(e).airfoil_rows + 1e-12);
  }
}

}  // namespace
}  // namespace bb
