// Pairing modes by shape (checks/mode_matching) and by label (checks/checks, match = "label"): a
// reordered or refined mode set must be compared mode to mode, a repeated eigenvalue as a pair,
// and a reference mode without a partner must fail its check entries, not borrow a neighbour's.
#include "checks/mode_matching.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/modal_analysis.hpp"
#include "checks/checks.hpp"
#include "common/errors.hpp"
#include "mesh/hex_block.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

// A clamped 1 m steel bar of square section, hex20 nx x n x n: its bending modes come in exactly
// repeated pairs (the two lateral directions), between them the torsion and axial modes.
Model square_bar(int nx, int n) {
  HexBlockSpec b;
  b.corners = {Eigen::Vector3d(0, 0, 0), {1, 0, 0},      {1, 0.05, 0}, {0, 0.05, 0}, {0, 0, 0.05}, {1, 0, 0.05},
               {1, 0.05, 0.05},          {0, 0.05, 0.05}};
  b.nx = nx;
  b.ny = n;
  b.nz = n;
  b.element = ElementType::hex20;
  Model model;
  model.mesh = generate_hex_block(b);
  model.section = {2.1e11, 0.3, 7850.0, 0.0};
  for (int i = 0; i < model.mesh.n_nodes(); ++i)
    if (std::abs(model.mesh.coords(i, 0)) < 1e-12) model.node_sets["clamp"].push_back(i);
  model.constraints.push_back({"clamp", {0, 1, 2}, 0.0});
  return model;
}

ModalResult modes_of(const Model& model, int n) {
  ModalOptions o;
  o.n_modes = n;
  return solve_modal(model, o);
}

TEST(ModeMatching, AModeSetPairsWithItselfModeForModeWithUnitMac) {
  const Model bar = square_bar(8, 1);
  const ModalResult modes = modes_of(bar, 8);
  const ModeMatch m = match_modes_by_shape(bar.mesh, modes, bar.mesh, modes);
  EXPECT_EQ(m.common_nodes, bar.mesh.n_nodes());
  for (size_t j = 0; j < m.computed_of_reference.size(); ++j) {
    EXPECT_EQ(m.computed_of_reference[j], static_cast<int>(j));
    EXPECT_NEAR(m.match_mac[j], 1.0, 1e-9);
  }
}

// The reference lists the modes in another order (as a refined or stiffer mesh may): the pairing
// follows the shapes, not the index.
TEST(ModeMatching, ReorderedModesArePairedByShapeNotByIndex) {
  const Model bar = square_bar(8, 1);
  const ModalResult modes = modes_of(bar, 8);
  // Modes 7 (torsion) and 8 (axial) stand alone; 1-6 are three repeated bending pairs.
  ASSERT_GT(std::abs(modes.frequencies_hz[6] / modes.frequencies_hz[7] - 1), 1e-3);
  ModalResult reference = modes;
  std::swap(reference.shapes[6], reference.shapes[7]);
  std::swap(reference.frequencies_hz[6], reference.frequencies_hz[7]);
  const ModeMatch m = match_modes_by_shape(bar.mesh, modes, bar.mesh, reference);
  EXPECT_EQ(m.computed_of_reference[6], 7);
  EXPECT_EQ(m.computed_of_reference[7], 6);
  for (int j = 0; j < 6; ++j) EXPECT_EQ(m.computed_of_reference[static_cast<size_t>(j)], j);
}

// A repeated pair has no preferred basis: the reference's pair, turned by 30 degrees inside its
// plane, matches the computed pair as a subspace (MAC 1) although each single MAC is 0.75 or 0.25.
TEST(ModeMatching, ARepeatedPairIsPairedAsASubspace) {
  const Model bar = square_bar(8, 1);
  const ModalResult modes = modes_of(bar, 4);
  ASSERT_NEAR(modes.frequencies_hz[0] / modes.frequencies_hz[1], 1.0, 1e-8) << "the first bending pair is repeated";
  ModalResult reference = modes;
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  reference.shapes[0] = c * modes.shapes[0] + s * modes.shapes[1];
  reference.shapes[1] = -s * modes.shapes[0] + c * modes.shapes[1];
  const ModeMatch m = match_modes_by_shape(bar.mesh, modes, bar.mesh, reference);
  EXPECT_LT(m.mac(0, 0), 0.95);  // one by one the pair would not match
  for (int j = 0; j < 2; ++j) {
    EXPECT_EQ(m.computed_of_reference[static_cast<size_t>(j)], j);
    EXPECT_NEAR(m.match_mac[static_cast<size_t>(j)], 1.0, 1e-9);
  }
}

// A mesh refined twice along every edge shares every node of the coarse mesh (hex20: the coarse
// mid-edge nodes are fine corners): the modes pair through them, mode for mode, MAC near 1.
TEST(ModeMatching, ARefinedMeshPairsWithTheCoarseOneThroughTheirCommonNodes) {
  const Model coarse = square_bar(8, 1), fine = square_bar(16, 2);
  const ModalResult coarse_modes = modes_of(coarse, 8), fine_modes = modes_of(fine, 8);
  const ModeMatch m = match_modes_by_shape(fine.mesh, fine_modes, coarse.mesh, coarse_modes);
  EXPECT_EQ(m.common_nodes, coarse.mesh.n_nodes());
  for (size_t j = 0; j < 8; ++j) {
    const int k = m.computed_of_reference[j];
    ASSERT_GE(k, 0);
    EXPECT_EQ(k, static_cast<int>(j)) << "this bar keeps its mode order under refinement";
    EXPECT_GT(m.match_mac[j], 0.99) << "reference mode " << j + 1;
    // The partner is the same mode, lower on the finer mesh (conforming elements, consistent mass:
    // the frequencies converge from above).
    EXPECT_LT(fine_modes.frequencies_hz[k], coarse_modes.frequencies_hz[static_cast<Eigen::Index>(j)])
        << "reference mode " << j + 1;
  }
  const ResultTable t = mode_match_table("mac_coarse", m, fine_modes, coarse_modes);
  EXPECT_EQ(t.columns[0], "mode");
  EXPECT_EQ(t.values.rows(), 8);
  EXPECT_EQ(t.values.cols(), 5 + 8);
}

TEST(ModeMatching, MeshesWithoutEnoughCommonNodesAreRefused) {
  const Model bar = square_bar(8, 1);
  Model shifted = bar;
  shifted.mesh.coords.col(0).array() += 0.0137;  // no node in common
  const ModalResult modes = modes_of(bar, 4);
  EXPECT_THROW(match_modes_by_shape(shifted.mesh, modes, bar.mesh, modes), InputError);
}

ResultTable labelled(const std::vector<double>& f, const std::vector<std::string>& type) {
  ResultTable t;
  t.name = "frequencies";
  t.columns = {"mode", "frequency_hz"};
  t.values.resize(static_cast<Eigen::Index>(f.size()), 2);
  for (size_t i = 0; i < f.size(); ++i) t.values.row(static_cast<Eigen::Index>(i)) << static_cast<double>(i + 1), f[i];
  t.add_text_column("type", type);
  return t;
}

// match = "label": the 2nd torsion of the reference is compared with the 2nd torsion computed, where
// the two runs order torsion and flexure differently; a label the run lacks fails its entry.
TEST(ModeMatching, LabelledRowsArePairedByTheirLabelsInOrder) {
  ResultTables computed, reference;
  computed.emplace("frequencies", labelled({100, 210, 300, 420}, {"flexure-x", "torsion", "flexure-x", "torsion"}));
  reference.emplace("frequencies",
                    labelled({101, 305, 205, 415, 500}, {"flexure-x", "flexure-x", "torsion", "torsion", "flexure-z"}));
  CheckSpec c;
  c.name = "by type";
  c.result = "frequencies";
  c.reference_result = "frequencies";
  c.key = "mode";
  c.compare = {{"frequency_hz", "frequency_hz"}};
  c.rel_tol = 0.05;
  c.match = CheckSpec::Match::label;
  c.labels = {"type"};
  const std::vector<CheckEntry> e = evaluate_check(c, computed, &reference);
  ASSERT_EQ(e.size(), 5u);
  EXPECT_EQ(e[1].computed_key, 3);  // reference 2 = 2nd flexure-x -> computed mode 3
  EXPECT_EQ(e[2].computed_key, 2);  // reference 3 = 1st torsion -> computed mode 2
  EXPECT_EQ(e[3].computed_key, 4);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(e[static_cast<size_t>(i)].pass) << e[static_cast<size_t>(i)].name;
  EXPECT_FALSE(e[4].pass) << "no flexure-z computed: " << e[4].name;
  EXPECT_TRUE(std::isnan(e[4].computed));
  // By key the same data would compare torsion with flexure and fail.
  c.match = CheckSpec::Match::key;
  c.keys = {1, 2, 3, 4};
  const std::vector<CheckEntry> by_key = evaluate_check(c, computed, &reference);
  EXPECT_FALSE(by_key[1].pass);
}

}  // namespace
}  // namespace bb
