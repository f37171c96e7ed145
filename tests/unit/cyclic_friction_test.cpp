// Friction dampers between the blades of a tuned bladed disk, by cyclic symmetry: one sector whose
// damper also touches the next blade (moving as its own blade shifted by the inter-blade phase
// 2 pi EO / N) against the whole ring of N blades and N dampers solved as one structure.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <optional>
#include <stdexcept>

#include "common/constants.hpp"
#include "friction/whole_ring.hpp"
#include "hbm/condensed_balance.hpp"
#include "hbm/cycle_energy.hpp"
#include "hbm/cyclic_shift.hpp"
#include "hbm/fixed_frequency.hpp"
#include "timeint/newmark.hpp"

namespace bb {
namespace {

using Eigen::Index;

// Sector DOFs: platform x (tangential) and y (radial), blade tip x, damper x and y. The damper is
// pressed up into two platforms by its centrifugal load: its own blade's and the next blade's.
constexpr Index kDofs = 5;
enum Dof : Index { px = 0, py = 1, tx = 2, dx = 3, dy = 4 };

struct Ring {
  int sectors = 6;
  double force = 3.0, centrifugal = 20.0;
  friction::PointParameters law{.kn = 1e6, .kt = 5e5, .mu = 0.5, .n0 = 0.0};

  void blade(friction::FrictionModel& m, Index o) const {
    m.mass.diagonal().segment(o, kDofs) << 0.2, 0.2, 0.3, 0.02, 0.02;
    m.stiffness(o + px, o + px) += 3e5;  // 2e5 to the disk, 1e5 to the tip
    m.stiffness(o + px, o + tx) -= 1e5;
    m.stiffness(o + tx, o + px) -= 1e5;
    m.stiffness(o + tx, o + tx) += 1e5;
    m.stiffness(o + py, o + py) += 1e7;  // radially stiff
    m.static_load[o + dy] = centrifugal;
  }
  static void finish(friction::FrictionModel& m) { m.damping = 2e-5 * m.stiffness; }

  // Damper of sector at offset o against the platform at offset p (its own blade or the next).
  friction::ContactElement contact(Index n, Index o, Index p) const {
    friction::ContactElement c;
    c.point = law;
    c.tangential = Eigen::RowVectorXd::Zero(n);
    c.normal = Eigen::RowVectorXd::Zero(n);
    c.tangential[o + dx] += 1.0;
    c.tangential[p + px] -= 1.0;
    c.normal[o + dy] += 1.0;
    c.normal[p + py] -= 1.0;
    return c;
  }

  friction::FrictionModel whole(int engine_order) const {
    const Index n = kDofs * sectors;
    friction::FrictionModel m{Eigen::MatrixXd::Zero(n, n), {},
                              Eigen::MatrixXd::Zero(n, n), {},
                              Eigen::VectorXd::Zero(n),    Eigen::VectorXcd::Zero(n)};
    const double phi = 2 * kPi * engine_order / sectors;
    for (int j = 0; j < sectors; ++j) {
      const Index o = kDofs * j, next = kDofs * ((j + 1) % sectors);
      blade(m, o);
      m.contacts.push_back(contact(n, o, o));
      m.contacts.push_back(contact(n, o, next));
      // Sector j moves as sector 0 shifted by j phi: its force leads by j phi.
      m.harmonic_load[o + tx] = force * std::polar(1.0, j * phi);
    }
    finish(m);
    return m;
  }

  friction::FrictionModel sector(int engine_order) const {
    friction::FrictionModel m{Eigen::MatrixXd::Zero(kDofs, kDofs), {},
                              Eigen::MatrixXd::Zero(kDofs, kDofs), {},
                              Eigen::VectorXd::Zero(kDofs),        Eigen::VectorXcd::Zero(kDofs)};
    blade(m, 0);
    m.harmonic_load[tx] = force;
    m.contacts.push_back(contact(kDofs, 0, 0));
    // The next blade's platform: its DOFs are this sector's, shifted in phase.
    friction::ContactElement next = contact(kDofs, 0, 0);
    next.tangential_next = Eigen::RowVectorXd::Zero(kDofs);
    next.tangential_next[px] = -1.0;
    next.tangential[px] = 0.0;
    next.normal_next = Eigen::RowVectorXd::Zero(kDofs);
    next.normal_next[py] = -1.0;
    next.normal[py] = 0.0;
    next.next_phase = 2 * kPi * engine_order / sectors;
    m.contacts.push_back(next);
    finish(m);
    return m;
  }
};

// The whole ring and the sector solved at omega, every DOF recovered; none (and a failure) when
// either does not converge.
struct SolvedPair {
  Eigen::MatrixXd whole, sector;
  hbm::HbmSolution solution;  // the sector's
};
std::optional<SolvedPair> solve_both(const hbm::HarmonicBalance& whole, const hbm::HarmonicBalance& sector,
                                     double omega) {
  const hbm::HbmSolution w = hbm::solve_at_frequency(whole, omega);
  const hbm::HbmSolution s = hbm::solve_at_frequency(sector, omega);
  if (!w.converged || !s.converged) {
    ADD_FAILURE() << "omega " << omega << ": " << (w.converged ? "sector: " + s.failure : "whole: " + w.failure);
    return std::nullopt;
  }
  return SolvedPair{whole.recover(w.x, omega), sector.recover(s.x, omega), s};
}

TEST(CyclicFriction, ShiftedCoefficientsAreTheMotionAdvancedByThePhase) {
  Eigen::VectorXd c(7);
  c << 0.3, 1.0, -0.5, 0.25, 0.75, -0.2, 0.1;
  const double phi = 2 * kPi * 5 / 12;
  const Eigen::VectorXd s = hbm::shift_coefficients(c, phi);
  auto value = [](const Eigen::VectorXd& k, double theta) {
    double v = k[0];
    for (Index h = 1; 2 * h < k.size(); ++h)
      v +=
          k[2 * h - 1] * std::cos(static_cast<double>(h) * theta) + k[2 * h] * std::sin(static_cast<double>(h) * theta);
    return v;
  };
  for (double theta : {0.0, 0.7, 2.1, 4.4}) EXPECT_NEAR(value(s, theta), value(c, theta + phi), 1e-14);
}

// The sector's harmonics equal sector 0's of the whole ring; sector 1 of the ring is sector 0
// advanced by the inter-blade phase; the sector's energy balances over a cycle.
TEST(CyclicFriction, SectorWithShiftedDamperEqualsTheWholeRing) {
  const Ring ring;
  hbm::HbmOptions options;
  options.harmonics = 3;
  // A multiple of N: the inter-blade shift is a whole number of samples, so the sampled AFT of the
  // whole ring is itself exactly a travelling wave (with 112 samples it is one only to the
  // sampling error, 6e-4 of the amplitude here).
  options.aft.samples = 96;
  bool slipped = false;
  for (int eo : {1, 2, 3}) {
    const hbm::HarmonicBalance whole(ring.whole(eo), options), sector(ring.sector(eo), options);
    if (eo == 1) {  // the ring built by hand is friction::whole_ring of the sector
      const friction::FrictionModel built = friction::whole_ring(ring.sector(eo), ring.sectors);
      EXPECT_EQ((built.stiffness - whole.model().stiffness).norm(), 0.0);
      EXPECT_LT((built.harmonic_load - whole.model().harmonic_load).norm(), 1e-14);
      ASSERT_EQ(built.contacts.size(), whole.model().contacts.size());
      for (size_t k = 0; k < built.contacts.size(); ++k) {
        EXPECT_EQ((built.contacts[k].tangential - whole.model().contacts[k].tangential).norm(), 0.0) << k;
        EXPECT_EQ((built.contacts[k].normal - whole.model().contacts[k].normal).norm(), 0.0) << k;
      }
    }
    for (double omega : {380.0, 450.0, 520.0}) {
      const std::optional<SolvedPair> pair = solve_both(whole, sector, omega);
      ASSERT_TRUE(pair) << "EO " << eo;
      const Eigen::MatrixXd &qw = pair->whole, &qs = pair->sector;
      const hbm::HbmSolution& s = pair->solution;
      const double scale = qs.cwiseAbs().maxCoeff();
      EXPECT_LT((qw.topRows(kDofs) - qs).cwiseAbs().maxCoeff(), 1e-6 * scale) << "EO " << eo << " omega " << omega;
      const double phi = 2 * kPi * eo / ring.sectors;
      for (Index d = 0; d < kDofs; ++d)
        EXPECT_LT(
            (qw.row(kDofs + d).transpose() - hbm::shift_coefficients(qw.row(d).transpose(), phi)).cwiseAbs().maxCoeff(),
            1e-6 * scale)
            << "EO " << eo << " omega " << omega << " dof " << d;
      const hbm::CycleEnergy e = hbm::cycle_energy(sector, s);
      EXPECT_GE(e.friction, -1e-12 * e.excitation);
      slipped = slipped || e.friction > 1e-3 * e.excitation;
      EXPECT_NEAR(e.excitation, e.viscous + e.friction + e.normal, 1e-6 * e.excitation);
    }
  }
  EXPECT_TRUE(slipped) << "no frequency made the dampers slip: the test would not see the friction";
}

// Blades coupled elastically to their neighbours (a disk): a spring kc from platform x of blade j
// to tip x of blade j + 1. In the travelling wave of nodal diameter k the sector's stiffness gains
// the Hermitian kc [1, -e^{i s}; -e^{-i s}, 1] on (px, tx), s = 2 pi k / N: complex for 0 < k < N/2,
// its conjugate for k > N/2. The sector with those operators per diameter equals the whole ring.
struct CoupledRing : Ring {
  double kc = 4e4;

  friction::FrictionModel whole(int engine_order) const {
    friction::FrictionModel m = Ring::whole(engine_order);
    const Index n = m.mass.rows();
    for (int j = 0; j < sectors; ++j) {
      const Index a = kDofs * j + px, b = (kDofs * (j + 1) + tx) % n;
      m.stiffness(a, a) += kc;
      m.stiffness(b, b) += kc;
      m.stiffness(a, b) -= kc;
      m.stiffness(b, a) -= kc;
    }
    finish(m);
    return m;
  }

  friction::FrictionModel sector(int engine_order) const {
    friction::FrictionModel m = Ring::sector(engine_order);
    friction::CyclicLinearModel& c = m.nodal_diameters;
    c.sectors = sectors;
    c.engine_order = engine_order;
    for (int k = 0; k < sectors; ++k) {
      const std::complex<double> shift = std::polar(1.0, 2 * kPi * k / sectors);
      Eigen::MatrixXcd stiffness = m.stiffness.cast<std::complex<double>>();
      stiffness(px, px) += kc;
      stiffness(tx, tx) += kc;
      stiffness(px, tx) -= kc * shift;
      stiffness(tx, px) -= kc * std::conj(shift);
      c.diameters.push_back({m.mass.cast<std::complex<double>>(), 2e-5 * stiffness, stiffness});
    }
    const Eigen::MatrixXcd& k0 = c.diameters.front().stiffness;
    m.stiffness = k0.real();
    finish(m);
    return m;
  }
};

TEST(CyclicFriction, DynamicStiffnessOfHarmonicHIsThatOfNodalDiameterHTimesEoModN) {
  CoupledRing ring;
  const friction::FrictionModel m = ring.sector(4);
  for (int h = 1; h <= 7; ++h) {
    const int k = (4 * h) % ring.sectors;
    const friction::NodalDiameterOperators& d = m.nodal_diameters.diameters[static_cast<size_t>(k)];
    const Eigen::MatrixXcd expected =
        d.stiffness + std::complex<double>(0.0, 300.0 * h) * d.damping - std::pow(300.0 * h, 2) * d.mass;
    EXPECT_EQ((friction::dynamic_stiffness(m, h, 300.0 * h) - expected).norm(), 0.0) << "h " << h;
  }
  EXPECT_EQ(friction::dynamic_stiffness(m, 0, 0.0).imag().norm(), 0.0);  // the static harmonic is ND 0
  EXPECT_THROW(timeint::NewmarkIntegrator(m, timeint::NewmarkOptions{}), std::invalid_argument);
}

TEST(CyclicFriction, SectorWithNodalDiameterOperatorsEqualsTheElasticallyCoupledRing) {
  const CoupledRing ring;
  hbm::HbmOptions options;
  options.harmonics = 3;
  options.aft.samples = 96;   // a multiple of N (see above)
  for (int eo : {1, 2, 4}) {  // 4: harmonic 1 in ND 4 = -2, the conjugate wave
    const hbm::HarmonicBalance whole(ring.whole(eo), options), sector(ring.sector(eo), options);
    for (double omega : {380.0, 450.0, 520.0}) {
      const std::optional<SolvedPair> pair = solve_both(whole, sector, omega);
      ASSERT_TRUE(pair) << "EO " << eo;
      EXPECT_LT((pair->whole.topRows(kDofs) - pair->sector).cwiseAbs().maxCoeff(),
                1e-6 * pair->sector.cwiseAbs().maxCoeff())
          << "EO " << eo << " omega " << omega;
      const hbm::CycleEnergy e = hbm::cycle_energy(sector, pair->solution);  // the Hermitian damping's share included
      EXPECT_NEAR(e.excitation, e.viscous + e.friction + e.normal, 1e-6 * e.excitation) << "EO " << eo;
    }
  }
}

TEST(CyclicFriction, OnlyTheHarmonicBalanceSolvesACyclicContact) {
  const Ring ring;
  EXPECT_THROW(timeint::NewmarkIntegrator(ring.sector(1), timeint::NewmarkOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace bb
