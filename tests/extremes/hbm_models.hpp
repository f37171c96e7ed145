// Small friction-contact models for the HBM stress matrix (tests/extremes) and the HBM benchmarks
// (bench/bench_hbm.cpp): a 3-DOF blade tied to the ground by one Jenkins contact, and two planar
// 2-DOF blades coupled by the rigid underplatform damper of damper/rigid_damper.hpp. Units: SI.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <complex>

#include "../unit/damper_support.hpp"
#include "damper/rigid_damper.hpp"
#include "frf/receptance.hpp"
#include "friction/jenkins.hpp"
#include "hbm/harmonic_balance.hpp"

namespace bb::hbm::models {

inline Eigen::RowVectorXd unit_row(Eigen::Index n, Eigen::Index i) {
  Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(n);
  r[i] = 1.0;
  return r;
}

// A blade of three DOFs (also the model of tests/unit/hbm_harmonic_balance_test.cpp): DOF 0 root (excited, no contact),
// 1 platform tangential (u = q1), 2 platform normal (v = q2, a push along +q2 presses). Modal damping zeta on every
// mode; `static_push` is an extra static force on DOF 2 [N].
inline friction::FrictionModel blade_on_ground(const friction::PointParameters& law, double force, double zeta = 0.01,
                                               double static_push = 0.0) {
  friction::FrictionModel m;
  m.stiffness.resize(3, 3);
  m.stiffness << 2.0e6, -5.0e5, -2.0e5, -5.0e5, 1.5e6, 3.0e5, -2.0e5, 3.0e5, 1.0e6;
  m.mass = Eigen::Vector3d(1.0, 0.4, 0.3).asDiagonal();
  m.damping = modal_damping_matrix(m.stiffness, m.mass, zeta);
  m.contacts.push_back({law, unit_row(3, 1), unit_row(3, 2)});
  m.static_load = Eigen::Vector3d(0.0, 0.0, static_push);
  m.harmonic_load = Eigen::VectorXcd::Zero(3);
  m.harmonic_load[0] = force;
  return m;
}

// Two planar blades, each reduced to its platform point (x, y), q = [x1, y1, x2, y2, xd, yd, theta]:
// blade 1 carries the damper's flat face (L1 and L2 on its platform point), blade 2 the cylindrical
// face (R). Blade stiffness ~1e6 N/m with x-y coupling, masses 0.5 and 0.45 kg (slightly mistuned,
// so that no two modes coincide); the damper is the asymmetric one of tests/unit/damper_support.hpp
// (beta_L = 40, beta_R = 55 deg, m = 0.04 kg, J = 1.5e-6 kg m^2). Every contact gets `law` (N0 of
// the law on top of CF); CF presses the damper into its seat; the harmonic force Fe cos(omega t)
// acts on blade 1 along x. Modal damping zeta on the blades only: the damper has no stiffness of
// its own (K_cc singular, closed by the contacts), and every DOF is a contact DOF.
inline damper::RigidDamper planar_damper() {
  damper::AsymmetricDamperGeometry g = damper::test::asymmetric_geometry();
  g.l1_x = 0, g.l1_y = 1, g.l2_x = 0, g.l2_y = 1, g.r_x = 2, g.r_y = 3;
  return damper::asymmetric_damper(g);
}

inline constexpr double kCentrifugalForce = 300.0;  // [N]

inline friction::FrictionModel planar_blades_with_damper(const friction::PointParameters& law, double force,
                                                         double zeta, double cf = kCentrifugalForce) {
  Eigen::Matrix4d kb = Eigen::Matrix4d::Zero(), mb = Eigen::Vector4d(0.5, 0.5, 0.45, 0.45).asDiagonal();
  kb.topLeftCorner<2, 2>() << 1.0e6, 2.0e5, 2.0e5, 1.5e6;
  kb.bottomRightCorner<2, 2>() << 1.1e6, -1.5e5, -1.5e5, 1.4e6;
  const damper::RigidDamper d = planar_damper();
  const damper::CoupledSystem s = damper::assemble_coupled_system(mb, kb, d);
  const damper::ContactKinematics k = damper::contact_kinematics(d, 4);
  friction::FrictionModel m;
  m.mass = s.mass;
  m.stiffness = s.stiffness;
  m.damping = Eigen::MatrixXd::Zero(7, 7);
  m.damping.topLeftCorner(4, 4) = modal_damping_matrix(kb, mb, zeta);
  for (Eigen::Index c = 0; c < k.tangential.rows(); ++c)
    m.contacts.push_back({law, k.tangential.row(c), k.normal.row(c)});
  m.static_load = damper::centrifugal_load(4, cf);
  m.harmonic_load = Eigen::VectorXcd::Zero(7);
  m.harmonic_load[0] = force;
  return m;
}

// The resonance seen from the forced DOF with every contact stuck (springs kn on a_n, kt on a_t):
// the mode with the largest modal receptance phi_f^2 / w^2 at DOF `forced` (mass-normalized phi).
// A reference frequency to place points below, at and above resonance, not a nonlinear peak.
inline double stuck_resonance(const friction::FrictionModel& m, Eigen::Index forced) {
  Eigen::MatrixXd k = m.stiffness;
  for (const friction::ContactElement& c : m.contacts)
    k += c.point.kn * c.normal.transpose() * c.normal + c.point.kt * c.tangential.transpose() * c.tangential;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k, m.mass);
  double best = -1.0, omega = 0.0;
  for (Eigen::Index r = 0; r < eig.eigenvalues().size(); ++r) {
    const double w2 = eig.eigenvalues()[r];
    if (!(w2 > 0.0)) continue;
    const double phi = eig.eigenvectors()(forced, r), score = phi * phi / w2;
    if (score > best) best = score, omega = std::sqrt(w2);
  }
  return omega;
}

}  // namespace bb::hbm::models
