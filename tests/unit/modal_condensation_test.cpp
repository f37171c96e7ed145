// The condensation onto the contact DOFs by modal superposition against the factorization of
// D_oo (friction::Condensation) on a 6-DOF chain with a free body among the contact DOFs: the same
// condensed stiffness, load and recovered DOFs; and the models it must refuse (damping not
// diagonal in the modes, a massless DOF).
#include "hbm/modal_condensation.hpp"

#include <gtest/gtest.h>

#include <complex>

namespace bb::hbm {
namespace {

using Index = Eigen::Index;
using Complex = std::complex<double>;

// Masses 1..5 kg in a chain of springs (1e6 N/m) grounded at DOF 0, DOF 5 a 0.3 kg body tied to nothing
// (a damper held only by its contacts); contact DOFs 1, 3 and 5. Rayleigh damping on the chain.
friction::FrictionModel chain(double alpha, double beta) {
  const Index n = 6;
  friction::FrictionModel m;
  m.mass = Eigen::MatrixXd::Zero(n, n);
  m.stiffness = Eigen::MatrixXd::Zero(n, n);
  m.stiffness(0, 0) = 1e6;  // to the ground
  for (Index i = 0; i < 5; ++i) {
    m.mass(i, i) = 1.0 + static_cast<double>(i);
    if (i == 0) continue;
    m.stiffness(i - 1, i - 1) += 1e6;
    m.stiffness(i, i) += 1e6;
    m.stiffness(i, i - 1) -= 1e6;
    m.stiffness(i - 1, i) -= 1e6;
  }
  m.mass(5, 5) = 0.3;
  m.damping = alpha * m.mass + beta * m.stiffness;
  m.harmonic_load = Eigen::VectorXcd::Zero(n);
  m.harmonic_load[0] = Complex(2.0, -1.0);
  m.harmonic_load[2] = 0.5;
  return m;
}

const std::vector<Index> kContact = {1, 3, 5}, kOther = {0, 2, 4};

Eigen::MatrixXcd dynamic_stiffness(const friction::FrictionModel& m, double w) {
  return m.stiffness.cast<Complex>() + Complex(0.0, w) * m.damping.cast<Complex>() - w * w * m.mass.cast<Complex>();
}

TEST(ModalCondensation, IsTheSchurComplementOfTheOtherDofsWithItsLoadAndRecovery) {
  const friction::FrictionModel m = chain(3.0, 2e-5);
  const std::optional<ModalBasis> basis = ModalBasis::of(m, kContact, kOther);
  ASSERT_TRUE(basis);
  for (const double w : {50.0, 700.0, 1500.0, 9000.0}) {
    const ModalCondensation modal = basis->at(w);
    const friction::Condensation<Complex> direct(dynamic_stiffness(m, w), kContact, kOther);
    const double scale = direct.reduced().norm();
    EXPECT_LT((modal.reduced() - direct.reduced()).norm(), 1e-10 * scale) << w;
    const auto modal_load = modal.condense(m.harmonic_load);
    const auto direct_load = direct.condense(m.harmonic_load);
    EXPECT_LT((modal_load.contact - direct_load.contact).norm(), 1e-10 * direct_load.contact.norm()) << w;
    const Eigen::VectorXcd x_c = Eigen::Vector3cd(Complex(1e-5, 2e-6), Complex(-3e-6, 0.0), Complex(4e-6, 1e-6));
    const Eigen::VectorXcd x_o = direct.recover(direct_load, x_c);
    EXPECT_LT((modal.recover(modal_load, x_c) - x_o).norm(), 1e-10 * x_o.norm()) << w;
    EXPECT_GT(modal.rcond(), 1e-8);
  }
}

TEST(ModalCondensation, IsRefusedWhereTheDampingCouplesTheModesOrAMassIsZero) {
  friction::FrictionModel coupled = chain(3.0, 2e-5);
  coupled.damping(0, 0) += 50.0;  // a local damper: C no longer diagonal in the modes
  EXPECT_FALSE(ModalBasis::of(coupled, kContact, kOther));
  friction::FrictionModel massless = chain(3.0, 2e-5);
  massless.mass(2, 2) = 0.0;
  EXPECT_FALSE(ModalBasis::of(massless, kContact, kOther));
  friction::FrictionModel undamped = chain(0.0, 0.0);
  EXPECT_TRUE(ModalBasis::of(undamped, kContact, kOther));
}

}  // namespace
}  // namespace bb::hbm
