// Linear receptances (frf/receptance): modal superposition and the direct dense solve against the
// closed forms of one- and two-DOF oscillators, reciprocity, residual flexibility, Rayleigh and
// modal damping, undamped resonances and linearity in the force. Units: SI.
#include "frf/receptance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/constants.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

using Complex = std::complex<double>;

struct Chain {
  Eigen::MatrixXd stiffness, mass;
};

// Masses in a row joined by springs; springs[0] grounds the first mass, springs[n] the last (0 = free).
Chain spring_chain(const std::vector<double>& masses, const std::vector<double>& springs) {
  const auto n = static_cast<Eigen::Index>(masses.size());
  Chain c{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    c.mass(i, i) = masses[static_cast<size_t>(i)];
    c.stiffness(i, i) = springs[static_cast<size_t>(i)] + springs[static_cast<size_t>(i) + 1];
    if (i + 1 < n) c.stiffness(i, i + 1) = c.stiffness(i + 1, i) = -springs[static_cast<size_t>(i) + 1];
  }
  return c;
}

// Two masses, three springs: modes near 115 Hz and 275 Hz.
Chain two_dof() { return spring_chain({1.5, 0.8}, {2.0e6, 5.0e5, 1.0e6}); }

struct Modes {
  Eigen::VectorXd omega;   // rad/s
  Eigen::MatrixXd shapes;  // mass-normalized
};

Modes dense_modes(const Chain& c) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(c.stiffness, c.mass);
  return {es.eigenvalues().cwiseMax(0.0).cwiseSqrt(), es.eigenvectors()};
}

ModalReceptance all_dofs(const Modes& modes, const Eigen::VectorXd& zeta) {
  return {.omega = modes.omega, .zeta = zeta, .shapes_out = modes.shapes, .shapes_in = modes.shapes, .residual = {}};
}

// Full receptance matrix by direct solves, one unit force per column.
Eigen::MatrixXcd direct_matrix(const Chain& c, const Eigen::MatrixXd& damping, double w) {
  const Eigen::Index n = c.stiffness.rows();
  Eigen::MatrixXcd h(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    h.col(j) = direct_response(c.stiffness, damping, c.mass, w, Eigen::VectorXcd::Unit(n, j));
  return h;
}

double relative(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) { return (a - b).norm() / b.norm(); }

TEST(Receptance, OneDofModalAndDirectEqualTheClosedForm) {
  const double k = 1.0e6, m = 2.0, zeta = 0.02, wn = std::sqrt(k / m), c = 2.0 * zeta * std::sqrt(k * m);
  const Chain one{Eigen::MatrixXd::Constant(1, 1, k), Eigen::MatrixXd::Constant(1, 1, m)};
  const ModalReceptance modal{.omega = Eigen::VectorXd::Constant(1, wn),
                              .zeta = Eigen::VectorXd::Constant(1, zeta),
                              .shapes_out = Eigen::MatrixXd::Constant(1, 1, 1.0 / std::sqrt(m)),
                              .shapes_in = Eigen::MatrixXd::Constant(1, 1, 1.0 / std::sqrt(m)),
                              .residual = {}};
  const Eigen::MatrixXd damping = modal_damping_matrix(one.stiffness, one.mass, zeta);
  EXPECT_NEAR(damping(0, 0), c, 1e-12 * c);
  for (double ratio : {0.0, 0.3, 0.99, 1.0, 1.01, 1.7, 10.0}) {
    const double w = ratio * wn;
    const Complex exact = 1.0 / Complex(k - m * w * w, c * w);
    EXPECT_NEAR(std::abs(modal.at(w)(0, 0) - exact), 0.0, 1e-12 * std::abs(exact)) << "w / wn = " << ratio;
    const Complex direct = direct_response(one.stiffness, damping, one.mass, w, Eigen::VectorXcd::Ones(1))[0];
    EXPECT_NEAR(std::abs(direct - exact), 0.0, 1e-12 * std::abs(exact)) << "w / wn = " << ratio;
  }
}

TEST(Receptance, OneDofStaticLimitIsTheFlexibility) {
  const double k = 3.0e7, m = 0.4, zeta = 0.05;
  const Chain one{Eigen::MatrixXd::Constant(1, 1, k), Eigen::MatrixXd::Constant(1, 1, m)};
  const Modes modes = dense_modes(one);
  const Eigen::MatrixXd damping = modal_damping_matrix(one.stiffness, one.mass, zeta);
  const ModalReceptance modal = all_dofs(modes, Eigen::VectorXd::Constant(1, zeta));
  // The damping term vanishes only linearly: |H k - 1| ~ 2 zeta w / wn near w = 0.
  for (double ratio : {0.0, 1e-6}) {
    const double w = ratio * modes.omega[0], tolerance = (1e-14 + 2.0 * zeta * ratio) / k;
    EXPECT_NEAR(std::abs(modal.at(w)(0, 0) - 1.0 / k), 0.0, tolerance);
    EXPECT_NEAR(std::abs(direct_response(one.stiffness, damping, one.mass, w, Eigen::VectorXcd::Ones(1))[0] - 1.0 / k),
                0.0, tolerance);
  }
}

TEST(Receptance, TwoDofModalSuperpositionEqualsTheDirectSolveWithModalDamping) {
  const Chain c = two_dof();
  const Modes modes = dense_modes(c);
  const double zeta = 0.01;
  const Eigen::MatrixXd damping = modal_damping_matrix(c.stiffness, c.mass, zeta);
  // The damping matrix is diagonal in the modes with 2 zeta w_r on the diagonal.
  const Eigen::MatrixXd modal_c = modes.shapes.transpose() * damping * modes.shapes;
  EXPECT_NEAR(modal_c(0, 0), 2 * zeta * modes.omega[0], 1e-10 * modal_c(0, 0));
  EXPECT_NEAR(modal_c(1, 1), 2 * zeta * modes.omega[1], 1e-10 * modal_c(1, 1));
  EXPECT_NEAR(modal_c(0, 1), 0.0, 1e-10 * modal_c(1, 1));
  const ModalReceptance modal = all_dofs(modes, Eigen::VectorXd::Constant(2, zeta));
  const double w1 = modes.omega[0], w2 = modes.omega[1];
  for (double w : {0.0, 0.5 * w1, w1, 0.5 * (w1 + w2), w2, 2.0 * w2, 20.0 * w2})
    EXPECT_LT(relative(modal.at(w), direct_matrix(c, damping, w)), 1e-10) << "w = " << w;
}

TEST(Receptance, TwoDofRayleighDampingHasTheModalRatiosOfItsFit) {
  const Chain c = two_dof();
  const Modes modes = dense_modes(c);
  // Fitted at frequencies other than the modes': the modal ratios then follow from the formula.
  const RayleighCoefficients r = fit_rayleigh(2 * kPi * 80.0, 0.01, 2 * kPi * 400.0, 0.03);
  const Eigen::MatrixXd damping = r.alpha * c.mass + r.beta * c.stiffness;
  Eigen::VectorXd zeta(2);
  for (Eigen::Index i = 0; i < 2; ++i) zeta[i] = r.alpha / (2 * modes.omega[i]) + r.beta * modes.omega[i] / 2;
  const ModalReceptance modal = all_dofs(modes, zeta);
  for (double w : {0.0, 0.7 * modes.omega[0], modes.omega[0], modes.omega[1], 3.0 * modes.omega[1]})
    EXPECT_LT(relative(modal.at(w), direct_matrix(c, damping, w)), 1e-10) << "w = " << w;
}

TEST(Receptance, FitRayleighReproducesBothTargetRatios) {
  const double w1 = 2 * kPi * 174.85, w2 = 2 * kPi * 5000.0;
  for (auto [z1, z2] : {std::pair{0.01, 0.01}, std::pair{0.005, 0.02}, std::pair{0.03, 0.001}}) {
    const RayleighCoefficients r = fit_rayleigh(w1, z1, w2, z2);
    EXPECT_NEAR(r.alpha / (2 * w1) + r.beta * w1 / 2, z1, 1e-14);
    EXPECT_NEAR(r.alpha / (2 * w2) + r.beta * w2 / 2, z2, 1e-14);
  }
  // Equal ratios: the textbook alpha = 2 zeta w1 w2 / (w1 + w2), beta = 2 zeta / (w1 + w2).
  const RayleighCoefficients equal = fit_rayleigh(w1, 0.01, w2, 0.01);
  EXPECT_NEAR(equal.alpha, 2 * 0.01 * w1 * w2 / (w1 + w2), 1e-12 * equal.alpha);
  EXPECT_NEAR(equal.beta, 2 * 0.01 / (w1 + w2), 1e-12 * equal.beta);
  EXPECT_THROW(fit_rayleigh(w1, 0.01, w1, 0.02), std::invalid_argument);
  EXPECT_THROW(fit_rayleigh(0.0, 0.01, w2, 0.02), std::invalid_argument);
}

TEST(Receptance, TransferReceptancesAreReciprocal) {
  // A full (consistent-like) mass matrix couples the DOFs in both K and M.
  Chain c = spring_chain({1.0, 2.0, 1.5}, {4.0e6, 1.0e6, 2.0e6, 3.0e5});
  c.mass(0, 1) = c.mass(1, 0) = 0.3;
  c.mass(1, 2) = c.mass(2, 1) = 0.2;
  const Modes modes = dense_modes(c);
  const RayleighCoefficients r = fit_rayleigh(modes.omega[0], 0.02, modes.omega[2], 0.01);
  const Eigen::MatrixXd rayleigh = r.alpha * c.mass + r.beta * c.stiffness;
  const Eigen::MatrixXd modal_c = modal_damping_matrix(c.stiffness, c.mass, 0.02);
  const ModalReceptance modal = all_dofs(modes, Eigen::VectorXd::Constant(3, 0.02));
  for (double w : {0.4 * modes.omega[0], modes.omega[1], 1.3 * modes.omega[2]}) {
    for (const Eigen::MatrixXcd& h : {modal.at(w), direct_matrix(c, rayleigh, w), direct_matrix(c, modal_c, w)})
      for (Eigen::Index i = 0; i < 3; ++i)
        for (Eigen::Index j = 0; j < i; ++j) EXPECT_NEAR(std::abs(h(i, j) - h(j, i)), 0.0, 1e-12 * h.norm());
  }
}

TEST(Receptance, ResidualFlexibilityRestoresTheStaticResponseOfTruncatedModes) {
  const Chain c = spring_chain({1.0, 1.0, 1.0}, {1.0e6, 1.0e6, 1.0e6, 1.0e6});
  const Modes modes = dense_modes(c);
  const double zeta = 0.01;
  const Eigen::MatrixXd flexibility = c.stiffness.inverse();
  const ModalReceptance full = all_dofs(modes, Eigen::VectorXd::Constant(3, zeta));
  ModalReceptance one_mode{.omega = modes.omega.head(1),
                           .zeta = Eigen::VectorXd::Constant(1, zeta),
                           .shapes_out = modes.shapes.leftCols(1),
                           .shapes_in = modes.shapes.leftCols(1),
                           .residual = {}};
  ModalReceptance with_residual = one_mode;
  with_residual.residual = residual_flexibility(flexibility, one_mode.shapes_out, one_mode.shapes_in, one_mode.omega);

  EXPECT_LT(relative(with_residual.at(0.0), flexibility.cast<Complex>()), 1e-12);
  EXPECT_GT(relative(one_mode.at(0.0), flexibility.cast<Complex>()), 0.1);
  // Below the first mode the truncated modes act almost statically; what the residual misses grows
  // like (w / w2)^2. Measured error ratio with / without: 0.003 at 0.1 w1, 0.024 at 0.3 w1, 0.067 at 0.5 w1.
  for (auto [ratio, factor] : {std::pair{0.1, 0.01}, std::pair{0.3, 0.05}, std::pair{0.5, 0.1}}) {
    const double w = ratio * modes.omega[0];
    const double without = relative(one_mode.at(w), full.at(w)), with = relative(with_residual.at(w), full.at(w));
    EXPECT_LT(with, factor * without) << "w / w1 = " << ratio;
  }
  EXPECT_THROW(residual_flexibility(flexibility, one_mode.shapes_out, one_mode.shapes_in, Eigen::VectorXd::Zero(1)),
               std::invalid_argument);
}

TEST(Receptance, UndampedResonanceIsASolverErrorAndOffResonanceIsFinite) {
  const Chain c = two_dof();
  const Modes modes = dense_modes(c);
  const Eigen::MatrixXd no_damping = Eigen::MatrixXd::Zero(2, 2);
  for (Eigen::Index r = 0; r < 2; ++r) {
    EXPECT_THROW(direct_response(c.stiffness, no_damping, c.mass, modes.omega[r], Eigen::VectorXcd::Ones(2)),
                 SolverError);
    EXPECT_THROW(direct_response(c.stiffness, {}, c.mass, modes.omega[r], Eigen::VectorXcd::Ones(2)), SolverError);
  }
  try {
    direct_response(c.stiffness, no_damping, c.mass, modes.omega[0], Eigen::VectorXcd::Ones(2));
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find(" Hz"), std::string::npos) << e.what();
  }
  const ModalReceptance undamped = all_dofs(modes, Eigen::VectorXd::Zero(2));
  EXPECT_THROW(undamped.at(modes.omega[1]), SolverError);
  for (double w : {0.0, 0.999 * modes.omega[0], 1.001 * modes.omega[0], 1.5 * modes.omega[1]}) {
    const Eigen::MatrixXcd h = undamped.at(w);
    EXPECT_TRUE(h.allFinite());
    EXPECT_LT(relative(h, direct_matrix(c, Eigen::MatrixXd(), w)), 1e-9) << "w = " << w;
  }
}

TEST(Receptance, ModalDampingLeavesRigidModesUndampedAndNeedsAPositiveMass) {
  const Chain free_free = spring_chain({1.0, 3.0}, {0.0, 2.0e6, 0.0});
  const Eigen::MatrixXd damping = modal_damping_matrix(free_free.stiffness, free_free.mass, 0.02);
  EXPECT_NEAR(Eigen::Vector2d(damping * Eigen::Vector2d::Ones()).norm(), 0.0, 1e-10 * damping.norm());
  const Modes modes = dense_modes(free_free);
  const double elastic = modes.shapes.col(1).dot(damping * modes.shapes.col(1));
  EXPECT_NEAR(elastic, 2 * 0.02 * modes.omega[1], 1e-10 * elastic);

  const Chain c = two_dof();
  EXPECT_THROW(modal_damping_matrix(c.stiffness, Eigen::Vector2d(1.0, 0.0).asDiagonal(), 0.01), SolverError);
  EXPECT_THROW(modal_damping_matrix(c.stiffness, Eigen::Vector2d(1.0, -1.0).asDiagonal(), 0.01), SolverError);
  EXPECT_THROW(modal_damping_matrix(c.stiffness, c.mass, -0.01), std::invalid_argument);
}

TEST(Receptance, ResponseScalesLinearlyFromMicroToMeganewtons) {
  const Chain c = two_dof();
  const Modes modes = dense_modes(c);
  const Eigen::MatrixXd damping = modal_damping_matrix(c.stiffness, c.mass, 0.01);
  const ModalReceptance modal = all_dofs(modes, Eigen::VectorXd::Constant(2, 0.01));
  const Eigen::VectorXcd unit(Eigen::Vector2cd(Complex(1.0, 0.0), Complex(-0.5, 0.25)));
  for (double w : {0.3 * modes.omega[0], modes.omega[1]}) {
    const Eigen::VectorXcd reference = direct_response(c.stiffness, damping, c.mass, w, unit);
    for (double scale : {1e-6, 1e6}) {
      const Eigen::VectorXcd direct = direct_response(c.stiffness, damping, c.mass, w, scale * unit);
      const Eigen::VectorXcd superposed = modal.at(w) * (scale * unit);
      EXPECT_LT(relative(direct / scale, reference), 1e-14) << "scale " << scale;
      EXPECT_LT(relative(superposed / scale, reference), 1e-10) << "scale " << scale;
    }
  }
}

}  // namespace
}  // namespace bb

namespace bb {
namespace {

// Damping per mode, as a modal test gives it: the modal matrix Phi^T C Phi is diag(2 zeta_r w_r)
// with each mode's own ratio, and the direct solve then equals the modal superposition with those
// ratios at every frequency.
TEST(Receptance, PerModeDampingGivesEachModeItsOwnRatio) {
  const Chain c = spring_chain({1.0, 2.0, 1.5}, {1.0e6, 5.0e5, 8.0e5, 0.0});
  const Modes modes = dense_modes(c);
  const Eigen::Vector3d zetas(0.002, 0.01, 0.03);
  const Eigen::MatrixXd damping = modal_damping_matrix(c.stiffness, c.mass, zetas);
  const Eigen::MatrixXd modal = modes.shapes.transpose() * damping * modes.shapes;
  for (Eigen::Index r = 0; r < 3; ++r)
    for (Eigen::Index s = 0; s < 3; ++s)
      EXPECT_NEAR(modal(r, s), r == s ? 2.0 * zetas[r] * modes.omega[r] : 0.0, 1e-9 * modal.norm());
  const ModalReceptance superposed = all_dofs(modes, zetas);
  for (double w : {0.5 * modes.omega[0], modes.omega[0], modes.omega[1], modes.omega[2]}) {
    const Eigen::MatrixXcd a = superposed.at(w), b = direct_matrix(c, damping, w);
    EXPECT_LT((a - b).norm(), 1e-9 * a.norm()) << w;
  }
  // One ratio for all is the scalar form; a wrong count is refused.
  EXPECT_LT((modal_damping_matrix(c.stiffness, c.mass, Eigen::Vector3d::Constant(0.02)) -
             modal_damping_matrix(c.stiffness, c.mass, 0.02))
                .norm(),
            1e-12 * damping.norm());
  EXPECT_THROW((void)modal_damping_matrix(c.stiffness, c.mass, Eigen::Vector2d(0.01, 0.02)), std::invalid_argument);
}

}  // namespace
}  // namespace bb
