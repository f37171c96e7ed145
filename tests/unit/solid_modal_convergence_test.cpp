// 3D modal analysis of a clamped square bar (hex blocks, assembly, Lanczos): the first bending
// pair and the first axial mode converge to beam theory as the hex20 mesh is refined.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/modal_analysis.hpp"
#include "model/build_model.hpp"

namespace bb {
namespace {

constexpr double kE = 2.1e11, kNu = 0.3, kRho = 7850.0, kL = 1.0, kA = 0.05;

Model clamped_bar(int nx, int n_section, ElementType element) {
  HexBlockSpec b;
  b.corners = {Eigen::Vector3d(0, 0, 0),    Eigen::Vector3d(kL, 0, 0), Eigen::Vector3d(kL, kA, 0),
               Eigen::Vector3d(0, kA, 0),   Eigen::Vector3d(0, 0, kA), Eigen::Vector3d(kL, 0, kA),
               Eigen::Vector3d(kL, kA, kA), Eigen::Vector3d(0, kA, kA)};
  b.nx = nx;
  b.ny = n_section;
  b.nz = n_section;
  b.element = element;
  Model m;
  m.mesh = generate_hex_block(b);
  m.section = {kE, kNu, kRho, 0.0};
  NodeSetSpec clamp;
  clamp.name = "clamp";
  clamp.equals[0] = 0.0;
  m.node_sets["clamp"] = select_nodes(m.mesh, clamp);
  m.constraints.push_back({"clamp", {0, 1, 2}, 0.0});
  return m;
}

// Euler-Bernoulli first bending and the rod's first axial frequency.
double bending_1() {
  const double i = std::pow(kA, 4) / 12.0, area = kA * kA;
  return std::pow(1.87510407, 2) / (2 * std::numbers::pi) * std::sqrt(kE * i / (kRho * area * std::pow(kL, 4)));
}
double axial_1() { return std::sqrt(kE / kRho) / (4 * kL); }

// The mode whose effective mass lies mostly along `axis`, lowest first.
double first_mode_along(const ModalResult& r, int axis) {
  for (Eigen::Index k = 0; k < r.frequencies_hz.size(); ++k)
    if (r.effective_mass_fraction(k, axis) > 0.3) return r.frequencies_hz[k];
  return NAN;
}

TEST(SolidModalConvergence, Hex20BarBendingAndAxialFrequenciesConvergeToBeamTheory) {
  ModalOptions options;
  options.n_modes = 10;
  double previous_bending_error = INFINITY, previous_axial_error = INFINITY;
  for (int nx : {5, 10, 20}) {
    const ModalResult r = solve_modal(clamped_bar(nx, 2, ElementType::hex20), options);
    const double bending_error = std::abs(first_mode_along(r, 1) / bending_1() - 1.0);
    const double axial_error = std::abs(first_mode_along(r, 0) / axial_1() - 1.0);
    EXPECT_LT(bending_error, previous_bending_error) << "nx = " << nx;
    EXPECT_LE(axial_error, previous_axial_error + 1e-6) << "nx = " << nx;
    previous_bending_error = bending_error;
    previous_axial_error = axial_error;
  }
  // L/h = 20: shear and rotary inertia move bending by ~0.1%; lateral inertia moves the rod mode by ~0.2%.
  EXPECT_LT(previous_bending_error, 0.005);
  EXPECT_LT(previous_axial_error, 0.005);
}

TEST(SolidModalConvergence, Hex8LocksInBendingWhereHex8IncompatibleDoesNot) {
  ModalOptions options;
  options.n_modes = 4;
  const double locked = solve_modal(clamped_bar(20, 2, ElementType::hex8), options).frequencies_hz[0] / bending_1();
  const double free = solve_modal(clamped_bar(20, 2, ElementType::hex8i), options).frequencies_hz[0] / bending_1();
  EXPECT_GT(locked, 1.10);
  EXPECT_NEAR(free, 1.0, 0.01);
}

}  // namespace
}  // namespace bb
