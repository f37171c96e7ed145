// Generalized-alpha integration of the floating-frame equations (ffrf/ffrf_integrator): second-order
// convergence against the exact solution of a constant-speed problem with rotating gravity, the
// steady state as an equilibrium, the constant-speed response oscillating about the static
// centrifugal deflection at the rotating modal frequency, the energy balance of a prescribed spin-up
// with gravity, energy and angular-momentum balances of a free rotor under a torque, the free rotor
// with a heavy hub against the prescribed constant speed, the modal basis against the nodal one,
// and the input errors. Units: SI.
#include "ffrf/ffrf_integrator.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "assembly/assemble.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "ffrf/rotating_modes.hpp"
#include "ffrf_test_models.hpp"

namespace bb {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A stocky steel beam in the plane, offset from the axis (its centre line at y = offset), so that the
// centrifugal load bends it and the sudden start excites its first mode.
test::BeamSpec offset_beam(ElementType type = ElementType::q4) {
  test::BeamSpec b;
  b.length = 0.5;
  b.width = 0.04;
  b.depth = 0.01;
  b.root_radius = 0.2;
  b.poisson_ratio = 0.3;
  b.element = type;
  b.nx = 20;
  b.ny = 2;
  return b;
}

Model offset_model(const test::BeamSpec& b, double offset) {
  Model m = test::beam_model(b);
  for (int n = 0; n < m.mesh.n_nodes(); ++n) m.mesh.coords(n, 1) += offset;
  return m;
}

// Exact solution of M q'' + 2 W G q' + K_eff q = W^2 f_c + F_g R(W t)^T g from rest (constant speed W,
// 2D, theta0 = 0): first-order form x' = A x + b0 + Re(B e^{iWt}); R^T g = Re(e^{iWt} (g + i a~ g)).
struct ExactConstantSpeed {
  Eigen::MatrixXcd v, v_inv;
  Eigen::VectorXcd lambda, x_h0, xp;
  VectorXd xs;
  double w;
  VectorXd at(double t) const {
    const Eigen::VectorXcd modal = (lambda * t).array().exp().matrix().cwiseProduct(x_h0);
    const Eigen::VectorXcd x =
        xs.cast<std::complex<double>>() + xp * std::exp(std::complex<double>(0.0, w * t)) + v * modal;
    return x.real();
  }
};

ExactConstantSpeed exact_constant_speed(const ffrf::ProjectedBody& p, double w, const Eigen::Vector2d& g) {
  const MatrixXd m = p.mass.to_dense(),
                 k = p.stiffness.to_dense() + w * w * (p.geometric_stiffness.to_dense() - p.projected_mass.to_dense());
  const MatrixXd gy = p.gyroscopic.to_dense();
  const auto n = m.rows();
  MatrixXd a = MatrixXd::Zero(2 * n, 2 * n);
  const MatrixXd mi = m.inverse();
  a.topRightCorner(n, n).setIdentity();
  a.bottomLeftCorner(n, n) = -mi * k;
  a.bottomRightCorner(n, n) = -mi * (2.0 * w) * gy;
  VectorXd b0 = VectorXd::Zero(2 * n);
  b0.tail(n) = mi * (w * w * p.centrifugal_load);
  const Eigen::Vector2d ag(-g[1], g[0]);  // a~ g, a = +z
  const Eigen::VectorXcd fg = p.gravity_load * (g.cast<std::complex<double>>() + std::complex<double>(0, 1) * ag);
  Eigen::VectorXcd bc = Eigen::VectorXcd::Zero(2 * n);
  bc.tail(n) = mi.cast<std::complex<double>>() * fg;
  ExactConstantSpeed e;
  e.w = w;
  e.xs = -a.fullPivLu().solve(b0);
  const Eigen::MatrixXcd shifted =
      std::complex<double>(0, w) * Eigen::MatrixXcd::Identity(2 * n, 2 * n) - a.cast<std::complex<double>>();
  e.xp = shifted.fullPivLu().solve(bc);
  const Eigen::EigenSolver<MatrixXd> eig(a);
  e.v = eig.eigenvectors();
  e.lambda = eig.eigenvalues();
  e.v_inv = e.v.inverse();
  // x = xs + Re(xp e^{iwt}) + V e^{Lt} c with x(0) = 0: c = -V^-1 (xs + Re xp).
  e.x_h0 = e.v_inv * (-(e.xs + e.xp.real())).cast<std::complex<double>>();
  return e;
}

double max_error_constant_speed(const test::FfrfSetup& s, double w, const Eigen::Vector2d& g, double dt, double t_end,
                                double rho, const ExactConstantSpeed& exact) {
  ffrf::FfrfOptions o;
  o.time_step = dt;
  o.end_time = t_end;
  o.rho_infinity = rho;
  o.gravity = Eigen::Vector3d(g[0], g[1], 0.0);
  const ffrf::FfrfHistory h = ffrf::integrate(*s.projected, ffrf::RotationProfile::constant_speed(w), o);
  // The elastic coordinates at the end, relative to the largest exact value over the run.
  const auto n = s.projected->n();
  double scale = 0.0;
  for (int i = 0; i <= 50; ++i) scale = std::max(scale, exact.at(t_end * i / 50.0).head(n).norm());
  return (h.final_coordinates - exact.at(h.time.back()).head(n)).norm() / scale;
}

TEST(FfrfIntegrator, ConstantSpeedWithRotatingGravityConvergesAtSecondOrder) {
  // A 4-mode basis (every mode resolved by the time steps used) of the offset beam: the
  // exact solution of the 4-DOF linear system is the reference.
  const test::BeamSpec b = offset_beam();
  const test::FfrfSetup s = test::ffrf_setup(offset_model(b, 0.05), test::modal_basis(4, false));
  const double f1 = s.basis->frequencies_hz[0], f4 = s.basis->frequencies_hz[3];
  const double w = 0.3 * 2 * kPi * f1;     // well below the divergence
  const Eigen::Vector2d g(3.0e3, -1.0e3);  // large, so that gravity matters against the centrifugal load
  const ExactConstantSpeed exact = exact_constant_speed(*s.projected, w, g);
  const double t_end = 3.0 / f1;
  for (const double rho : {1.0, 0.9, 0.5}) {
    double previous = 0.0;
    for (const int per_period : {40, 80, 160, 320}) {
      const double dt = 1.0 / (f4 * per_period);
      const double err = max_error_constant_speed(s, w, g, dt, t_end, rho, exact);
      if (previous > 0.0) {
        const double order = std::log2(previous / err);
        std::printf("  rho_inf %.1f, %3d steps per period of the highest mode: error %.3e, order %.3f\n", rho,
                    per_period, err, order);
        EXPECT_GT(order, 1.9);
        EXPECT_LT(order, 2.2);
      }
      previous = err;
    }
  }
}

TEST(FfrfIntegrator, SteadyStateStartIsAnEquilibriumAtConstantSpeed) {
  const test::BeamSpec b = offset_beam();
  for (const bool modal : {false, true}) {
    const test::FfrfSetup s =
        test::ffrf_setup(offset_model(b, 0.05), modal ? test::modal_basis(8) : ffrf::ElasticBasisOptions{});
    const double speed = 0.5 * ffrf::divergence_speed(*s.projected, false);
    ffrf::FfrfOptions o;
    o.time_step = 1e-4;
    o.end_time = 2e-2;
    o.start_from_steady_state = true;
    const ffrf::FfrfHistory h = ffrf::integrate(*s.projected, ffrf::RotationProfile::constant_speed(speed), o);
    const ffrf::StaticDeflection st = ffrf::centrifugal_deflection(*s.body, speed);
    const VectorXd q = ffrf::to_free_dofs(*s.basis, h.final_coordinates);
    EXPECT_LT((q - st.displacement).norm(), (modal ? 1e-3 : 1e-10) * st.displacement.norm())
        << (modal ? "modal" : "nodal");
    EXPECT_EQ(h.factorizations, 1);
  }
}

// Zero crossings of y - mean, linearly interpolated: (mean period, mean value over whole periods).
std::pair<double, double> period_and_mean(const std::vector<double>& t, const std::vector<double>& y, double about) {
  std::vector<double> up;
  for (size_t i = 1; i < y.size(); ++i)
    if (y[i - 1] - about < 0.0 && y[i] - about >= 0.0)
      up.push_back(t[i - 1] + (about - y[i - 1]) / (y[i] - y[i - 1]) * (t[i] - t[i - 1]));
  const double period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
  double sum = 0.0, span = 0.0;
  for (size_t i = 1; i < y.size(); ++i) {
    if (t[i] <= up.front() || t[i - 1] >= up.back()) continue;
    const double dt = t[i] - t[i - 1];
    sum += 0.5 * (y[i] + y[i - 1]) * dt;
    span += dt;
  }
  return {period, sum / span};
}

TEST(FfrfIntegrator, ConstantSpeedResponseOscillatesAboutTheStaticDeflectionAtTheRotatingFrequency) {
  const test::BeamSpec b = offset_beam();
  const Model model = offset_model(b, 0.05);
  const test::FfrfSetup s = test::ffrf_setup(model, test::modal_basis(10));
  const double w = 0.6 * 2 * kPi * s.basis->frequencies_hz[0];
  const ffrf::RotatingModes rm = ffrf::rotating_modes(*s.projected, w, {.n_modes = 2});
  const double f1 = rm.frequencies_hz[0];
  const int dof = test::tip_dof(model, b, 1);
  ffrf::FfrfOptions o;
  o.time_step = 1.0 / (100 * f1);
  o.end_time = 30.0 / f1;
  o.output_dofs = {dof};
  const ffrf::FfrfHistory h = ffrf::integrate(*s.projected, ffrf::RotationProfile::constant_speed(w), o);
  const ffrf::StaticDeflection st = ffrf::centrifugal_deflection(*s.body, w);
  const double u_static = ffrf::expand_to_global(*s.body, st.displacement)[dof];
  std::vector<double> y(h.time.size());
  for (size_t i = 0; i < y.size(); ++i) y[i] = h.displacement(static_cast<Eigen::Index>(i), 0);
  const auto [period, mean] = period_and_mean(h.time, y, u_static);
  const double amplitude = *std::max_element(y.begin(), y.end()) - u_static;
  std::printf(
      "  Omega %.2f rad/s: static tip u_y %.6e m, mean %.6e m (%+.2e), amplitude %.3e m; period %.6e s vs "
      "rotating mode %.6e s (%+.2e); %d factorization(s)\n",
      w, u_static, mean, mean / u_static - 1, amplitude, period, 1.0 / f1, period * f1 - 1, h.factorizations);
  EXPECT_NEAR(mean / u_static, 1.0, 2e-3);
  EXPECT_NEAR(period * f1, 1.0, 1e-3);             // gen-alpha period error at 100 steps/period: ~3e-4
  EXPECT_GT(amplitude, 0.5 * std::abs(u_static));  // the sudden start really excites the mode
  EXPECT_EQ(h.factorizations, 1);                  // constant speed: one factorization for the whole run
}

// Spin-up with gravity: T + U change = work of the driving torque + work of gravity.
TEST(FfrfIntegrator, PrescribedSpinUpBalancesEnergyWithDrivingAndGravityWork) {
  const test::BeamSpec b = offset_beam();
  const test::FfrfSetup s = test::ffrf_setup(offset_model(b, 0.05), test::modal_basis(8));
  const double f1 = s.basis->frequencies_hz[0];
  const double w_final = 0.5 * 2 * kPi * f1, ramp = 20.0 / f1;
  double previous = 0.0;
  for (const int per_period : {20, 40, 80}) {
    ffrf::FfrfOptions o;
    o.time_step = 1.0 / (per_period * f1);
    o.end_time = 1.5 * ramp;
    o.rho_infinity = 1.0;
    o.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    const ffrf::FfrfHistory h = ffrf::integrate(*s.projected, ffrf::RotationProfile::spin_up(w_final, ramp), o);
    double t_max = 0.0, w_max = 0.0;
    for (size_t i = 0; i < h.time.size(); ++i) {
      t_max = std::max(t_max, h.kinetic_energy[i]);
      w_max = std::max({w_max, std::abs(h.driving_work[i]), std::abs(h.gravity_work[i])});
    }
    const double err = h.energy_balance_error() / t_max;
    // The reported driving torque integrates to the driving work (trapezoid over the samples).
    double torque_work = 0.0;
    for (size_t i = 1; i < h.time.size(); ++i)
      torque_work += 0.5 * (h.time[i] - h.time[i - 1]) *
                     (h.driving_torque[i] * h.speed[i] + h.driving_torque[i - 1] * h.speed[i - 1]);
    EXPECT_NEAR(torque_work / h.driving_work.back(), 1.0, per_period == 80 ? 1e-4 : 1e-2);
    std::printf(
        "  %2d steps per period: energy balance error %.3e of max T (%.4g J); driving work %.4g J, largest "
        "work %.3g J; observed order %.2f\n",
        per_period, err, t_max, h.driving_work.back(), w_max, previous > 0 ? std::log2(previous / err) : 0.0);
    if (per_period == 80) {
      EXPECT_LT(err, 1e-5);
    }
    previous = err;
  }
}

// A free rotor driven by tau(t) = tau0 sin^2(pi t / t1) for t < t1, then coasting: without gravity
// and damping d(T + U)/dt = tau Omega and dH/dt = tau (ffrf/ffrf_integrator.hpp).
TEST(FfrfIntegrator, FreeRotorBalancesEnergyAndAngularMomentumUnderATorque) {
  const test::BeamSpec b = offset_beam();
  const double f1 = test::ffrf_setup(offset_model(b, 0.05), test::modal_basis(2)).basis->frequencies_hz[0];
  for (const bool modal : {true, false}) {
    const test::FfrfSetup s =
        test::ffrf_setup(offset_model(b, 0.05), modal ? test::modal_basis(8) : ffrf::ElasticBasisOptions{});
    const double t1 = 10.0 / f1, j_rotor = 0.02;
    // Brings the rotor to about 0.3 times the first natural frequency (the impulse is tau0 t1 / 2).
    const double tau0 = 0.3 * 2 * kPi * f1 * (j_rotor + s.body->mass_properties.axis_inertia) / (0.5 * t1);
    auto torque = [=](double t) { return t < t1 ? tau0 * std::pow(std::sin(kPi * t / t1), 2) : 0.0; };
    ffrf::FfrfOptions o;
    o.time_step = 1.0 / (40 * f1);
    o.end_time = 2.0 * t1;
    o.rotor_inertia = j_rotor;
    o.rho_infinity = 1.0;
    const ffrf::FfrfHistory h = ffrf::integrate(*s.projected, ffrf::RotationProfile::free(torque), o);
    const double impulse = 0.5 * tau0 * t1;  // integral of tau over the run
    const double h_end = h.angular_momentum.back() - h.angular_momentum.front();
    double t_max = 0.0, coast_drift = 0.0;
    for (size_t i = 0; i < h.time.size(); ++i) {
      t_max = std::max(t_max, h.kinetic_energy[i]);
      if (h.time[i] >= t1)
        coast_drift = std::max(coast_drift, std::abs(h.angular_momentum[i] - h.angular_momentum.back()));
    }
    const double e_err = h.energy_balance_error() / t_max;
    std::printf(
        "  %s basis: Omega_end %.3f rad/s; energy balance error %.2e of max T; Delta H %.9f vs impulse %.9f "
        "(%.2e); H drift while coasting %.2e; Newton %ld iterations, max %d per step, %d factorizations\n",
        modal ? "modal" : "nodal", h.speed.back(), e_err, h_end, impulse, h_end / impulse - 1,
        coast_drift / std::abs(h.angular_momentum.back()), h.solve_iterations, h.max_step_iterations, h.factorizations);
    EXPECT_LT(e_err, 1e-4);
    EXPECT_NEAR(h_end / impulse, 1.0, 1e-4);
    EXPECT_LT(coast_drift, 1e-9 * std::abs(h.angular_momentum.back()));
    EXPECT_GT(h.speed.back(), 0.1);
  }
}

// With a hub far heavier than the blade, a free rotor spinning at Omega0 without torque keeps
// Omega0 to O(J_blade / J_hub): its deflection history must approach the prescribed constant speed.
// Damping and an external load in the body frame enter the ledger: T + U change = driving + gravity
// + external work - damping work, with the load from the model's nodal loads (assembly/load_vector).
TEST(FfrfIntegrator, DampedRunWithAnExternalLoadBalancesEnergy) {
  const test::BeamSpec b = offset_beam();
  Model model = offset_model(b, 0.05);
  model.loads = {{"tip", 1, 50.0, LoadSplit::equal}};
  const test::FfrfSetup s = test::ffrf_setup(model, test::modal_basis(8));
  const double f1 = s.basis->frequencies_hz[0];
  const Eigen::VectorXd tip_load = ffrf::restrict_to_free(*s.body, load_vector(s.model));
  ffrf::FfrfOptions o;
  o.time_step = 1.0 / (80 * f1);
  o.end_time = 20.0 / f1;
  o.rho_infinity = 1.0;
  o.rayleigh_mass = 0.02 * 2 * kPi * f1;  // about 1 % of critical at f1
  o.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
  o.external_load = [&](double t) { return Eigen::VectorXd(std::sin(2 * kPi * 1.3 * f1 * t) * tip_load); };
  const ffrf::FfrfHistory h =
      ffrf::integrate(*s.projected, ffrf::RotationProfile::spin_up(0.4 * 2 * kPi * f1, 10.0 / f1), o);
  double t_max = 0.0;
  for (double t : h.kinetic_energy) t_max = std::max(t_max, t);
  std::printf("  damping work %.4g J, external work %.4g J, driving work %.4g J; balance error %.2e of max T\n",
              h.damping_work.back(), h.external_work.back(), h.driving_work.back(), h.energy_balance_error() / t_max);
  EXPECT_GT(h.damping_work.back(), 0.0);
  EXPECT_GT(std::abs(h.external_work.back()), 0.0);
  EXPECT_LT(h.energy_balance_error(), 1e-5 * t_max);
  // ... and small against the damping and external works themselves (a wrong sign would be 100 %).
  EXPECT_LT(h.energy_balance_error(), 0.02 * (h.damping_work.back() + std::abs(h.external_work.back())));
}

TEST(FfrfIntegrator, FreeRotorWithAHeavyHubMatchesThePrescribedConstantSpeed) {
  const test::BeamSpec b = offset_beam();
  const Model model = offset_model(b, 0.05);
  const test::FfrfSetup s = test::ffrf_setup(model, test::modal_basis(8));
  const double f1 = s.basis->frequencies_hz[0], w = 0.5 * 2 * kPi * f1;
  ffrf::FfrfOptions o;
  o.time_step = 1.0 / (60 * f1);
  o.end_time = 5.0 / f1;
  o.output_dofs = {test::tip_dof(model, b, 1)};
  const ffrf::FfrfHistory prescribed = ffrf::integrate(*s.projected, ffrf::RotationProfile::constant_speed(w), o);
  double previous = 0.0;
  for (const double hub : {1e3, 1e4}) {
    o.rotor_inertia = hub * s.body->mass_properties.axis_inertia;
    const ffrf::FfrfHistory free =
        ffrf::integrate(*s.projected, ffrf::RotationProfile::free([](double) { return 0.0; }, w), o);
    const double diff = (free.displacement - prescribed.displacement).cwiseAbs().maxCoeff() /
                        prescribed.displacement.cwiseAbs().maxCoeff();
    std::printf("  J_hub = %.0e J_blade: max tip difference %.3e relative\n", hub, diff);
    if (previous > 0) {
      EXPECT_LT(diff, 0.2 * previous);  // ~ 1 / J_hub
    }
    previous = diff;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(FfrfIntegrator, ModalBasisReproducesTheNodalSpinUpWithMeasuredErrorAndSpeedUp) {
  const test::BeamSpec b = offset_beam();
  const Model model = offset_model(b, 0.05);
  const test::FfrfSetup nodal = test::ffrf_setup(model);
  const test::FfrfSetup modal = test::ffrf_setup(model, test::modal_basis(8));
  const double f1 = modal.basis->frequencies_hz[0];
  ffrf::FfrfOptions o;
  o.time_step = 1.0 / (40 * f1);
  o.end_time = 30.0 / f1;
  o.output_dofs = {test::tip_dof(model, b, 0), test::tip_dof(model, b, 1)};
  o.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
  const auto profile = ffrf::RotationProfile::spin_up(0.5 * 2 * kPi * f1, 15.0 / f1);
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const ffrf::FfrfHistory hn = ffrf::integrate(*nodal.projected, profile, o);
  const auto t1 = clock::now();
  const ffrf::FfrfHistory hm = ffrf::integrate(*modal.projected, profile, o);
  const auto t2 = clock::now();
  const double err = (hm.displacement - hn.displacement)
                         .cwiseAbs()
                         .colwise()
                         .maxCoeff()
                         .cwiseQuotient(hn.displacement.cwiseAbs().colwise().maxCoeff())
                         .maxCoeff();
  const double tn = std::chrono::duration<double>(t1 - t0).count(), tm = std::chrono::duration<double>(t2 - t1).count();
  std::printf(
      "  %d steps: nodal (%d DOFs) %.3f s, %d factorizations, %ld corrections; modal (%d coordinates) %.3f s "
      "(speed-up %.1f); max tip error %.2e of the peak\n",
      hn.steps, nodal.body->n_free(), tn, hn.factorizations, hn.solve_iterations, modal.basis->size(), tm, tn / tm,
      err);
  EXPECT_LT(err, 5e-3);
}

TEST(FfrfIntegrator, InvalidOptionsAreInputErrorsThatSayWhatToChange) {
  const test::FfrfSetup s = test::ffrf_setup(offset_model(offset_beam(), 0.0), test::modal_basis(4));
  const auto constant = ffrf::RotationProfile::constant_speed(10.0);
  auto expect_error = [&](ffrf::FfrfOptions o, const std::string& needle) {
    try {
      (void)ffrf::integrate(*s.projected, constant, o);
      ADD_FAILURE() << "expected InputError mentioning " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  ffrf::FfrfOptions ok;
  ok.time_step = 1e-3;
  ok.end_time = 1e-2;
  ffrf::FfrfOptions o = ok;
  o.time_step = 0.0;
  expect_error(o, "time_step must be > 0");
  o = ok;
  o.end_time = 1e-4;
  expect_error(o, "at least one time step");
  o = ok;
  o.rho_infinity = 1.5;
  expect_error(o, "rho_infinity");
  o = ok;
  o.output_stride = 0;
  expect_error(o, "output_stride");
  o = ok;
  o.gravity = Eigen::Vector3d(0, 0, -9.81);
  expect_error(o, "in the plane");
  o = ok;
  o.output_dofs = {100000};
  expect_error(o, "output DOF");
  EXPECT_THROW((void)ffrf::RotationProfile::spin_up(6.0, 0.0), InputError);
}

// The justification of the default rho_inf = 0.9 (ffrf_integrator.hpp): a mode resolved by 20 steps
// per period loses 1.385e-5 of its amplitude per period (spectral radius of Chung & Hulbert's
// amplification matrix at omega dt = 2 pi / 20, computed separately). One mode at rest under a
// suddenly applied gravity load: the oscillation energy about the static state, T + U - W_g - E_eq,
// must decay as that radius to the power 2 n.
TEST(FfrfIntegrator, DefaultRhoInfinityBarelyDampsResolvedModes) {
  const test::FfrfSetup s = test::ffrf_setup(offset_model(offset_beam(), 0.05), test::modal_basis(1, false));
  const double f1 = s.basis->frequencies_hz[0];
  const int periods = 200;
  ffrf::FfrfOptions o;
  o.time_step = 1.0 / (20 * f1);
  o.end_time = periods / f1;
  o.gravity = Eigen::Vector3d(0.0, -9.81e3, 0.0);
  const ffrf::FfrfHistory h = ffrf::integrate(*s.projected, ffrf::RotationProfile::constant_speed(0.0), o);
  // Static state: K q_s = f, equilibrium energy U_s - f q_s = -f q_s / 2; the start (q = 0) has 0.
  const double f = (s.projected->gravity_load * Eigen::Vector2d(0.0, -9.81e3))[0];
  const double q_s = f / s.projected->stiffness.dense()(0, 0);
  const double e_eq = -0.5 * f * q_s;
  const double e_end = h.kinetic_energy.back() + h.strain_energy.back() - h.gravity_work.back() - e_eq;
  const double ratio = std::sqrt(e_end / (0 - e_eq)), expected = std::pow(1.0 - 1.385e-5, periods);
  std::printf("  amplitude after %d periods at 20 steps per period: %.6f (predicted %.6f)\n", periods, ratio, expected);
  EXPECT_NEAR(ratio, expected, 5e-5);  // the loss itself is 2.8e-3; measured difference 2e-5
}

TEST(FfrfIntegrator, GeneralizedAlphaParametersAreChungHulberts) {
  const ffrf::GeneralizedAlpha trapezoidal = ffrf::chung_hulbert(1.0);
  EXPECT_DOUBLE_EQ(trapezoidal.alpha_m, 0.5);
  EXPECT_DOUBLE_EQ(trapezoidal.alpha_f, 0.5);
  EXPECT_DOUBLE_EQ(trapezoidal.gamma, 0.5);
  EXPECT_DOUBLE_EQ(trapezoidal.beta, 0.25);
  const ffrf::GeneralizedAlpha p = ffrf::chung_hulbert(0.9);
  EXPECT_DOUBLE_EQ(p.gamma, 0.5 - p.alpha_m + p.alpha_f);  // second order
}

}  // namespace
}  // namespace bb
