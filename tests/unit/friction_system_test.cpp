// The friction system (hbm/friction_system): the contact DOFs are exactly those some a_t or a_n
// touches, and the Schur condensation onto them plus the recovery of the others reproduces the
// full solve, for the real operator of the time domain and the complex one of a harmonic.
#include "friction/friction_system.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <vector>

namespace bb::hbm {
namespace {

using Eigen::Index;

friction::FrictionModel five_dofs() {
  friction::FrictionModel m;
  m.mass = Eigen::MatrixXd::Identity(5, 5);
  m.stiffness = Eigen::MatrixXd::Identity(5, 5);
  Eigen::RowVectorXd t = Eigen::RowVectorXd::Zero(5), n = Eigen::RowVectorXd::Zero(5);
  t[3] = 1.0;
  t[1] = -1.0;
  n[4] = 1.0;
  m.contacts.push_back({.point = {.kn = 1.0, .kt = 1.0, .mu = 0.1, .n0 = 0.0}, .tangential = t, .normal = n});
  return m;
}

template <class Scalar>
void condensed_solve_matches_the_full_solve(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& a,
                                            const friction::FrictionSystem& system) {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  const Vector f = Vector::Random(a.rows());
  const Vector full = a.partialPivLu().solve(f);
  const friction::Condensation<Scalar> d = system.condense(a);
  const typename friction::Condensation<Scalar>::Load load = d.condense(f);
  const Vector x_c = d.reduced().partialPivLu().solve(load.contact);
  const Vector x_o = d.recover(load, x_c);
  Vector z(a.rows());
  z(system.contact_dofs()) = x_c;
  z(system.other_dofs()) = x_o;
  EXPECT_LT((z - full).norm(), 1e-13 * full.norm());
  EXPECT_GT(d.rcond(), 1e-3);
}

TEST(FrictionSystem, ContactDofsAreThoseTheContactRowsTouch) {
  const friction::FrictionSystem system(five_dofs());
  EXPECT_EQ(system.contact_dofs(), (std::vector<Index>{1, 3, 4}));
  EXPECT_EQ(system.other_dofs(), (std::vector<Index>{0, 2}));
  ASSERT_EQ(system.contacts_on_c().size(), 1u);
  EXPECT_EQ(system.contacts_on_c()[0].tangential, Eigen::RowVector3d(-1.0, 1.0, 0.0));
  EXPECT_EQ(system.contacts_on_c()[0].normal, Eigen::RowVector3d(0.0, 0.0, 1.0));
}

TEST(FrictionSystem, CondensationAndRecoveryReproduceTheFullSolve) {
  const friction::FrictionSystem system(five_dofs());
  const Eigen::MatrixXd r = Eigen::MatrixXd::Random(5, 5);
  const Eigen::MatrixXd a = r * r.transpose() + 5.0 * Eigen::MatrixXd::Identity(5, 5);  // K_eff-like: SPD
  condensed_solve_matches_the_full_solve<double>(a, system);
  Eigen::MatrixXcd d = a.cast<std::complex<double>>();  // D_h-like: K - w^2 M + i w C
  d.imag() = 0.3 * Eigen::MatrixXd::Identity(5, 5);
  d.real() -= 2.0 * Eigen::MatrixXd::Identity(5, 5);
  condensed_solve_matches_the_full_solve<std::complex<double>>(d, system);
}

TEST(FrictionSystem, EveryDofAContactDofLeavesNothingToCondense) {
  friction::FrictionModel m = five_dofs();
  m.contacts[0].normal = Eigen::RowVectorXd::Ones(5);
  const friction::FrictionSystem system(m);
  EXPECT_TRUE(system.other_dofs().empty());
  const Eigen::MatrixXd a = 3.0 * Eigen::MatrixXd::Identity(5, 5);
  const friction::Condensation<double> d = system.condense(a);
  EXPECT_EQ(d.reduced(), a);
  EXPECT_EQ(d.recover(d.condense(Eigen::VectorXd::Ones(5)), Eigen::VectorXd::Ones(5)).size(), 0);
}

}  // namespace
}  // namespace bb::hbm
