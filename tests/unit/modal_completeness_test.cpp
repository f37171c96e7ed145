// Completeness of the modal solver: Lanczos from one start vector can miss one member of a repeated
// eigenvalue; the Sturm count (inertia of K - sigma M) must catch it, and a repeated eigenvalue
// that straddles the requested count must come back whole.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/modal_analysis.hpp"
#include "assembly/assemble.hpp"
#include "linalg/inertia.hpp"
#include "linalg/modal_solver.hpp"
#include "mesh/hex_block.hpp"

namespace bb {
namespace {

// A 10 x 10 x 1 m plate, hex8i 8 x 8 x 3, its four bottom edges held in x, y and z: symmetric under
// a quarter turn, so its spectrum has exactly repeated pairs (the report that exposed the defect).
Model square_plate() {
  HexBlockSpec b;
  b.corners = {
      Eigen::Vector3d(0, 0, 0), {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 1}, {10, 0, 1}, {10, 10, 1}, {0, 10, 1}};
  b.nx = 8;
  b.ny = 8;
  b.nz = 3;
  b.element = ElementType::hex8i;
  Model model;
  model.mesh = generate_hex_block(b);
  model.section = {2.1e11, 0.3, 7850.0, 0.0};
  std::vector<int> edges;
  for (int i = 0; i < model.mesh.n_nodes(); ++i) {
    const Eigen::Vector3d p = model.mesh.coords.row(i);
    const bool bottom = std::abs(p.z()) < 1e-9;
    if (bottom && (std::abs(p.x()) < 1e-9 || std::abs(p.x() - 10) < 1e-9 || std::abs(p.y()) < 1e-9 ||
                   std::abs(p.y() - 10) < 1e-9))
      edges.push_back(i);
  }
  model.node_sets["edges"] = edges;
  model.constraints.push_back({"edges", {0, 1, 2}, 0.0});
  return model;
}

struct PlateSystem {
  FreeSystem free;
  Eigen::VectorXd reference;  // the lowest 30 eigenvalues, from a run with a wide margin
};

const PlateSystem& plate() {
  static const PlateSystem s = [] {
    PlateSystem p;
    p.free = assemble_free_system(square_plate());
    ModalOptions o;
    o.n_modes = 30;
    o.subspace_size = 120;
    o.ordering = FillOrdering::metis;
    p.reference = lowest_modes(p.free.stiffness, p.free.mass, o).eigenvalues;
    return p;
  }();
  return s;
}

TEST(ModalCompleteness, SturmCountEqualsTheEigenvaluesBelowTheShift) {
  const PlateSystem& p = plate();
  for (int k : {3, 9, 17, 25}) {
    const double between = 0.5 * (p.reference[k - 1] + p.reference[k]);
    if (p.reference[k] - p.reference[k - 1] < 1e-6 * p.reference[k]) continue;  // inside a pair
    const InertiaCount c = eigenvalues_below(p.free.stiffness, p.free.mass, between);
    ASSERT_TRUE(c.ok) << c.message;
    EXPECT_EQ(c.negative, k) << "shift between modes " << k << " and " << k + 1;
  }
}

TEST(ModalCompleteness, TheSpectrumHasRepeatedPairs) {
  const PlateSystem& p = plate();
  int pairs = 0;
  for (Eigen::Index k = 1; k < p.reference.size(); ++k)
    pairs += p.reference[k] - p.reference[k - 1] < 1e-8 * p.reference[k] ? 1 : 0;
  EXPECT_GE(pairs, 3);
}

// Every requested count returns the same lowest eigenvalues as the wide reference run: no member of
// a pair is skipped, whichever count cuts the spectrum.
TEST(ModalCompleteness, NoModeOfAPairIsSkippedAtAnyRequestedCount) {
  const PlateSystem& p = plate();
  for (int n = 4; n <= 24; ++n) {
    ModalOptions o;
    o.n_modes = n;
    o.ordering = FillOrdering::metis;
    const ModalSolution s = lowest_modes(p.free.stiffness, p.free.mass, o);
    ASSERT_GE(s.eigenvalues.size(), n);
    for (Eigen::Index k = 0; k < s.eigenvalues.size(); ++k)
      EXPECT_NEAR(s.eigenvalues[k], p.reference[k], 1e-8 * p.reference[k]) << "n = " << n << ", mode " << k + 1;
    EXPECT_EQ(s.sturm_count, s.eigenvalues.size()) << "n = " << n;
  }
}

// The defect itself: without the count, Lanczos (one start vector) returns some repeated eigenvalue
// only once at some requested counts on this plate; the count catches every such case.
TEST(ModalCompleteness, UncheckedLanczosMissesAMemberOfAPairThatTheCountCatches) {
  const PlateSystem& p = plate();
  int missed = 0, rerun = 0;
  for (int n = 4; n <= 24; ++n) {
    ModalOptions o;
    o.n_modes = n;
    o.ordering = FillOrdering::metis;
    o.verify_count = false;
    const ModalSolution unchecked = lowest_modes(p.free.stiffness, p.free.mass, o);
    bool wrong = false;
    for (Eigen::Index k = 0; k < n; ++k)
      wrong = wrong || std::abs(unchecked.eigenvalues[k] - p.reference[k]) > 1e-8 * p.reference[k];
    o.verify_count = true;
    const ModalSolution checked = lowest_modes(p.free.stiffness, p.free.mass, o);
    missed += wrong ? 1 : 0;
    rerun += checked.lanczos_runs > 1 ? 1 : 0;
    if (wrong) {
      EXPECT_GT(checked.lanczos_runs, 1) << "n = " << n << ": a missed mode went unnoticed";
    }
  }
  std::printf("  requested counts 4..24: %d unchecked runs miss a mode, %d checked runs needed a second Lanczos run\n",
              missed, rerun);
  EXPECT_GT(missed, 0) << "this plate no longer exposes the defect: the test would pass without the count";
}

// The first n >= 3 such that modes n and n + 1 are a repeated pair; 0 when there is none.
int first_straddling_count(const Eigen::VectorXd& reference) {
  for (Eigen::Index k = 3; k < reference.size(); ++k)
    if (reference[k] - reference[k - 1] < 1e-8 * reference[k]) return static_cast<int>(k);
  return 0;
}

TEST(ModalCompleteness, APairThatStraddlesTheCountIsReturnedWhole) {
  const PlateSystem& p = plate();
  const int straddle = first_straddling_count(p.reference);
  ASSERT_GT(straddle, 0);
  ModalOptions o;
  o.n_modes = straddle;
  o.ordering = FillOrdering::metis;
  const ModalSolution s = lowest_modes(p.free.stiffness, p.free.mass, o);
  ASSERT_EQ(s.eigenvalues.size(), straddle + 1);
  EXPECT_NEAR(s.eigenvalues[straddle], s.eigenvalues[straddle - 1], 1e-8 * s.eigenvalues[straddle]);
}

// A larger verified solution serves a smaller request (the model cache does this) exactly as a run
// for that request would: the straddling pair whole, and nothing beyond what its count proves.
TEST(ModalCompleteness, LeadingModesOfALargerSolutionFollowTheSameRules) {
  const PlateSystem& p = plate();
  const int straddle = first_straddling_count(p.reference);
  ASSERT_GT(straddle, 0);
  ModalOptions o;
  o.n_modes = straddle + 4;
  o.ordering = FillOrdering::metis;
  const ModalSolution large = lowest_modes(p.free.stiffness, p.free.mass, o);
  o.n_modes = straddle;
  const std::optional<ModalSolution> served = leading_modes(large, o);
  ASSERT_TRUE(served.has_value());
  const ModalSolution direct = lowest_modes(p.free.stiffness, p.free.mass, o);
  ASSERT_EQ(served->eigenvalues.size(), direct.eigenvalues.size());  // straddle + 1: the pair whole
  for (Eigen::Index k = 0; k < direct.eigenvalues.size(); ++k)
    EXPECT_NEAR(served->eigenvalues[k], direct.eigenvalues[k], 1e-9 * direct.eigenvalues[k]);
  EXPECT_EQ(served->sturm_count, large.sturm_count);
  o.n_modes = static_cast<int>(large.eigenvalues.size()) + 1;
  EXPECT_FALSE(leading_modes(large, o).has_value());  // more than it holds
  ModalSolution unproven = large;
  unproven.sturm_shift = 0.5 * large.eigenvalues[straddle - 1];
  o.n_modes = straddle;
  EXPECT_FALSE(leading_modes(unproven, o).has_value());  // a cut above its count's shift
}

TEST(ModalCompleteness, ABandIsSizedByTheSturmCount) {
  const PlateSystem& p = plate();
  const Model model = square_plate();
  ModeSelection band;
  const double two_pi = 2 * M_PI;
  band.band_min_hz = std::sqrt(p.reference[4]) / two_pi * 0.999;
  band.band_max_hz = std::sqrt(0.5 * (p.reference[19] + p.reference[20])) / two_pi;
  const ModalResult r = solve_modal(model, p.free, band, {});
  int expected = 0;
  for (Eigen::Index k = 0; k < p.reference.size(); ++k) {
    const double f = std::sqrt(p.reference[k]) / two_pi;
    expected += f >= *band.band_min_hz && f <= *band.band_max_hz ? 1 : 0;
  }
  EXPECT_EQ(r.frequencies_hz.size(), expected);
}

}  // namespace
}  // namespace bb
