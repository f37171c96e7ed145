// A few uncoupled nonlinear modes at one co-located driven point, as modal testers of jointed
// structures fit two modes that lie near each other: each mode k answers the force F on its own,
//   m_k (w_k(a_k)^2 - w^2 + 2 i z_k(a_k) w_k(a_k) w) x_k = F,   a_k = |x_k|,
// (forced/single_mode_synthesis.hpp) and the point moves by x = sum_k x_k. The modes share the
// force but not their amplitudes: no mode's frequency or damping depends on another's motion.
// Phases are of x to the force, in radians, in [-pi, 0] for positive damping.
//
// Sensitivities are exact, per parameter of the modes in turn (each in NonlinearMode order:
// frequency knots, damping knots, mass): d x_k = x_k (d a_k / a_k + i d phi_k), so
// d|x| = Re(conj(x) dx) / |x| and d arg x = Im(conj(x) dx) / |x|^2.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "forced/single_mode_synthesis.hpp"

namespace bb {

struct MultiModePoint {
  double amplitude = 0.0;              // |x| [m]
  double phase = 0.0;                  // of x to the force [rad]
  double force = 0.0;                  // |F| [N]
  bool stable = true;                  // every mode on a stable branch
  bool holds = true;                   // a held point: |x| is the held amplitude (false: a fold's jump passes it)
  std::vector<double> mode_amplitude;  // a_k [m]
  Eigen::VectorXd d_amplitude, d_phase, d_force;  // per parameter of all modes (multi_mode_parameters)
};

// How many parameters the modes have together.
Eigen::Index multi_mode_parameters(const std::vector<NonlinearMode>& modes);

// Each mode's backbone_bounds, computed once per sweep.
std::vector<BackboneBounds> multi_mode_bounds(const std::vector<NonlinearMode>& modes);

// A force-controlled point: each mode stepped on its own from its own previous amplitude
// (`previous` one per mode, or empty: from rest), the responses summed. Throws
// std::invalid_argument as stepped_response.
MultiModePoint multi_mode_stepped(const std::vector<NonlinearMode>& modes, double force, double f_exc_hz,
                                  const std::vector<double>& previous, const std::vector<BackboneBounds>& bounds);

// A response-controlled point: the force that holds |x| = amplitude at f_exc, with each mode on
// the branch reached from rest (its smallest stable amplitude at that force), by a scan in log F
// for the smallest force that reaches the amplitude and bisection there (one mode: the closed
// form of held_response). Where a mode's fold jumps past the held amplitude no force holds it on
// those branches: the point is then the jump's force, `holds` false and `amplitude` what it
// reaches. Force sensitivities by the implicit function theorem, dF/dp = -(d|x|/dp)/(d|x|/dF);
// the phase's total, d phi/dp + d phi/dF dF/dp. Throws std::invalid_argument when no force up to
// 2^100 times the single modes' reaches the amplitude.
MultiModePoint multi_mode_held(const std::vector<NonlinearMode>& modes, double amplitude, double f_exc_hz,
                               const std::vector<BackboneBounds>& bounds);

}  // namespace bb
