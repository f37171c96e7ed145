// Modes of a rotating body linearized about its steady state at a constant speed Omega, the
// Campbell diagram over a list of speeds with its engine-order crossings, and the static
// centrifugal deflection. SI units; frequencies in Hz.
//
// At constant Omega the elastic equations (ffrf/ffrf_integrator.hpp) are linear with constant
// coefficients; their free motions q = phi e^{st} solve the quadratic eigenproblem
//   [M s^2 + 2 Omega G s + (K + s_st Omega^2 K_s1 - Omega^2 M_p)] phi = 0,
// (s_st = 1 with geometric stiffening, 2 Omega G dropped without Coriolis), solved here by its
// first-order (state-space) form [0 I; -M^-1 K_eff -M^-1 2 Omega G], dense, in the coordinates of an
// elastic basis: a modal basis of fixed-interface modes is exact enough for the lowest rotating
// modes (tests/unit/ffrf_rotating_modes_test.cpp measures it against the full model). G is skew and
// K_eff symmetric (a gyroscopic system): the eigenvalues are +-i omega while K_eff > 0; a real pair
// +-lambda is a static divergence (Meirovitch, Methods of Analytical Dynamics, ch. 6; spin-softening
// divergence of the linear model without stiffening, Kane, Ryan & Banerjee 1987).
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "ffrf/elastic_basis.hpp"

namespace bb::ffrf {

struct RotatingModesOptions {
  // Lowest modes reported per speed, at most the basis size. In a modal basis only the modes well
  // below its highest mode at rest are converged (its top Ritz values, those of the static shapes
  // in particular, are not): ask for fewer than ElasticBasis::mode_numbers holds.
  int n_modes = 6;
  bool stiffening = true;    // s_st Omega^2 K_s1
  bool coriolis = true;      // 2 Omega G
  int max_dense_size = 800;  // a nodal basis larger than this must be replaced by a modal one
};

struct RotatingModes {
  double speed = 0.0;  // Omega [rad/s]
  // Ascending: the oscillating modes Im(s) / 2 pi and, at frequency 0, the divergent ones.
  Eigen::VectorXd frequencies_hz;
  Eigen::VectorXd growth_rates;  // Re(s) [1/s] of the same modes: ~0 when stable, > 0 diverging
  bool stable = true;            // no eigenvalue with a positive real part (beyond round-off)
  double max_growth_rate = 0.0;  // [1/s]
};

// Throws InputError for a negative n_modes or a nodal basis above max_dense_size.
RotatingModes rotating_modes(const ProjectedBody& body, double speed, const RotatingModesOptions& options = {});

struct CampbellDiagram {
  std::vector<double> speeds;      // [rad/s]
  Eigen::MatrixXd frequencies_hz;  // speeds x modes, each row ascending (modes sorted, not tracked)
  std::vector<bool> stable;
};
CampbellDiagram campbell_diagram(const ProjectedBody& body, const std::vector<double>& speeds,
                                 const RotatingModesOptions& options = {});

struct EngineOrderCrossing {
  int engine_order = 0;
  int mode = 0;               // 1-based position in the ascending list
  double speed = 0.0;         // [rad/s]
  double frequency_hz = 0.0;  // = engine_order * speed / 2 pi
};
// Crossings of the mode lines with f = EO Omega / 2 pi, bracketed by the diagram's speeds and
// refined by the secant method on the eigenproblem (to 1e-10 relative in speed).
std::vector<EngineOrderCrossing> engine_order_crossings(const ProjectedBody& body, const CampbellDiagram& diagram,
                                                        const std::vector<int>& engine_orders,
                                                        const RotatingModesOptions& options = {});

// Time step resolving the `mode`-th lowest rotating mode at `speed` with `steps_per_period` steps:
// the generalized-alpha period error is (omega dt)^2 / 12, 0.2 % at 40 steps per period.
double time_step_resolving(const ProjectedBody& body, double speed, int mode = 1, int steps_per_period = 40,
                           const RotatingModesOptions& options = {});

// Lowest speed at which K + s_st Omega^2 K_s1 - Omega^2 M_p becomes singular (the static
// divergence), in the basis's coordinates; +infinity when it never does (stiffening dominates).
double divergence_speed(const ProjectedBody& body, bool stiffening);

struct StaticDeflectionOptions {
  bool stiffening = true;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // inertial frame [m/s^2]
  double angle = 0.0;                                 // theta at which gravity is taken [rad]
};
struct StaticDeflection {
  double speed = 0.0;
  Eigen::VectorXd displacement;  // free DOFs [m]
  double relative_residual = 0.0;
  double pivot_ratio = 0.0;  // min |D| / max |D| of the operator's LDL^T pivots
};
// (K + s_st Omega^2 K_s1 - Omega^2 M_p) u = Omega^2 f_c + F_g R(theta)^T g on the full model.
// Throws SolverError naming the speed when the operator is not positive definite (at or above the
// divergence speed: no stable steady state).
StaticDeflection centrifugal_deflection(const RotatingBody& body, double speed,
                                        const StaticDeflectionOptions& options = {});

}  // namespace bb::ffrf
