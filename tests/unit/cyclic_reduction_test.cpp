// Craig-Bampton reduction of a sector per nodal diameter: the ring's closed form, Hermitian
// operators, the conjugate wave, convergence to the nodal diameter's modes from above, and the cut
// that makes the sector's reductions span the whole structure's.
#include "cyclic/cyclic_reduction.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>

#include "bladed_disk_sector_fixture.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "cyclic/cyclic_modes.hpp"
#include "cyclic/whole_disk.hpp"
#include "reduction/craig_bampton.hpp"

namespace bb {
namespace {

Eigen::VectorXd spectrum_hz(const SectorReduction& r) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> eig(r.stiffness, r.mass, Eigen::EigenvaluesOnly);
  return eig.eigenvalues().array().max(0.0).sqrt() / (2 * kPi);
}

double hermitian_defect(const Eigen::MatrixXcd& a) { return (a - a.adjoint()).norm() / a.norm(); }

// A sector of a ring of masses m grounded by k0 and coupled by kc (DOF 0 its mass on the left
// face, DOF 1 the coupling spring's far end on the right face): w^2 = (k0 + 4 kc sin^2(s / 2)) / m.
TEST(CyclicReduction, RingSectorHasTheClosedFormAtAnyPhase) {
  const double m = 2.0, k0 = 3e4, kc = 5e4;
  Eigen::MatrixXd k(2, 2), mm = Eigen::MatrixXd::Zero(2, 2);
  k << k0 + kc, -kc, -kc, kc;
  mm(0, 0) = m;
  CyclicDofs cyclic;
  cyclic.sectors = 7;
  cyclic.dim = 1;
  cyclic.rotation = Eigen::MatrixXd::Identity(1, 1);
  cyclic.left = {0};
  cyclic.right = {1};
  for (int nd = 0; nd < 7; ++nd) {
    const double s = 2 * kPi * nd / 7;
    const SectorReduction r = cyclic_craig_bampton(k.sparseView(), mm.sparseView(), cyclic, s, {0}, 0.0, 0, {});
    ASSERT_EQ(r.stiffness.rows(), 1);
    EXPECT_NEAR(r.stiffness(0, 0).real(), k0 + 4 * kc * std::pow(std::sin(s / 2), 2), 1e-9 * k0) << "ND " << nd;
    EXPECT_NEAR(r.stiffness(0, 0).imag(), 0.0, 1e-9 * k0);
    EXPECT_NEAR(r.mass(0, 0).real(), m, 1e-12);
  }
  EXPECT_THROW(cyclic_craig_bampton(k.sparseView(), mm.sparseView(), cyclic, 0.0, {1}, 0.0, 0, {}), InputError);
}

struct Reduced : SectorSystem {
  Reduced() : SectorSystem(6) {
    for (const char* point : {"damper_left", "damper_right", "tip_lead"})
      for (int d = 0; d < 3; ++d) {
        const int node = model.node_sets.at(point).front();
        masters.push_back(system.dofs.equation[static_cast<size_t>(node * 3 + d)]);
      }
  }
  SectorReduction at(int nd, double cut_hz, int modes = 0) const {
    return cyclic_craig_bampton(system.stiffness, system.mass, cyclic, 2 * kPi * nd / 6, masters, cut_hz, modes, {});
  }
  std::vector<int> masters;
};

TEST(CyclicReduction, SectorOperatorsAreHermitianAndBoundTheNodalDiametersModesFromAbove) {
  const Reduced s;
  for (int nd : {0, 2, 3}) {
    const SectorReduction r = s.at(nd, 30000.0);
    EXPECT_LT(hermitian_defect(r.stiffness), 1e-12) << "ND " << nd;
    EXPECT_LT(hermitian_defect(r.mass), 1e-12) << "ND " << nd;
    if (nd == 0 || nd == 3) {
      EXPECT_LT(r.stiffness.imag().norm(), 1e-12 * r.stiffness.norm()) << "ND " << nd;
    } else {
      EXPECT_GT(r.stiffness.imag().norm(), 1e-6 * r.stiffness.norm());  // a travelling wave
    }
    for (Eigen::Index i = 0; i < r.mode_frequencies_hz.size(); ++i) EXPECT_LT(r.mode_frequencies_hz[i], 30000.0);
    // Craig-Bampton is a Rayleigh-Ritz method: each frequency at or above the exact one, and close.
    const NodalDiameterModes exact = nodal_diameter_modes(s.system.stiffness, s.system.mass, s.cyclic, nd, 3, {});
    const Eigen::VectorXd reduced = spectrum_hz(r);
    for (int f = 0; f < 3; ++f) {
      EXPECT_GE(reduced[f], exact.frequencies_hz[f] * (1 - 1e-9)) << "ND " << nd << " family " << f;
      EXPECT_LT(reduced[f], exact.frequencies_hz[f] * 1.01) << "ND " << nd << " family " << f;
    }
  }
}

TEST(CyclicReduction, NodalDiameterMinusKIsTheConjugateWave) {
  const Reduced s;
  const SectorReduction plus = s.at(2, 0.0, 8), minus = s.at(4, 0.0, 8);
  const Eigen::VectorXd a = spectrum_hz(plus), b = spectrum_hz(minus);
  ASSERT_EQ(a.size(), b.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-9 * a[i]) << i;
  // The masters' static (Guyan) block does not depend on the modes' basis: exactly conjugate.
  const Eigen::Index nb = plus.masters;
  EXPECT_LT((plus.stiffness.topLeftCorner(nb, nb).conjugate() - minus.stiffness.topLeftCorner(nb, nb)).norm(),
            1e-9 * plus.stiffness.topLeftCorner(nb, nb).norm());
}

TEST(CyclicReduction, TheCutKeepsWhatTheWholeStructuresReductionKeeps) {
  const Reduced s;
  const double cut = 30000.0;
  int sum = 0;
  for (int nd = 0; nd < 6; ++nd) sum += static_cast<int>(s.at(nd, cut).mode_frequencies_hz.size());
  const Model whole = whole_from_sector(s.model, 6, 1e-9);
  const FreeSystem w = assemble_free_system(whole);
  std::vector<int> masters;
  for (int j = 0; j < 6; ++j)
    for (const char* point : {"damper_left", "damper_right", "tip_lead"})
      for (int d = 0; d < 3; ++d) {
        const int node = whole.node_sets.at(std::string(point) + "@" + std::to_string(j)).front();
        masters.push_back(w.dofs.equation[static_cast<size_t>(node * 3 + d)]);
      }
  EXPECT_GT(sum, 6);
  EXPECT_EQ(fixed_interface_count(w.stiffness, w.mass, masters, cut), sum);
}

}  // namespace
}  // namespace bb
