// Single-nonlinear-mode synthesis: one mode whose natural frequency f(a) and damping ratio z(a)
// depend on the displacement amplitude a at the driven point (forced/modal_backbone.hpp), driven
// there by a harmonic force F at w = 2 pi f_exc and measured there (co-located):
//   m (w0(a)^2 - w^2 + 2 i z(a) w0(a) w) x = F,   w0 = 2 pi f(a),   a = |x|,
// with m the effective modal mass at the point. The data-driven rung of the joint ladder: modal
// testing of jointed structures fits such backbone and damping curves to phase-resonance or
// response-controlled tests (Szemplinska-Stupnicka's single nonlinear mode; Krack 2015 for its
// use with nonlinear modes). Any f(a) and z(a) are representable, so damping may grow several-fold
// while the frequency barely moves, which no Masing law allows. Phases are of the response to the
// force, in radians, in (-pi, 0] for positive damping.
//
// Sensitivities are exact, with respect to the parameters in this order: the frequency knots
// [Hz], the damping knots, the mass [kg] (implicit function theorem for force-controlled points).
#pragma once
#include <Eigen/Dense>

#include <optional>

#include "forced/modal_backbone.hpp"

namespace bb {

struct NonlinearMode {
  ModalBackbone frequency_hz;   // f(a) [Hz], a the displacement amplitude at the driven point [m]
  ModalBackbone damping_ratio;  // z(a), positive
  double mass = 1.0;            // effective modal mass at the driven point [kg]

  Eigen::Index parameters() const {
    return static_cast<Eigen::Index>(frequency_hz.knots() + damping_ratio.knots() + 1);
  }
};

struct ModalPoint {
  double amplitude = 0.0;                         // |x| [m]
  double phase = 0.0;                             // of x to the force [rad]
  double force = 0.0;                             // |F| [N]
  bool stable = true;                             // a force-controlled point on a branch d|F|/da > 0
  Eigen::VectorXd d_amplitude, d_phase, d_force;  // per parameter (NonlinearMode order)
  // Of a force-controlled point: d|x|/d|F| and d phase/d|F| along its branch (parameters held),
  // what several modes summed need to hold their total amplitude (forced/multi_mode_synthesis.hpp).
  double d_amplitude_d_force = 0.0, d_phase_d_force = 0.0;
};

// The force that holds amplitude a at f_exc, its phase, and their sensitivities (a held fixed).
ModalPoint held_response(const NonlinearMode& mode, double amplitude, double f_exc_hz);

// The backbone's extent and the ranges of f(a) and z(a) over its knots (sampled): what bounds the
// roots of every force-controlled point of one mode, computed once per sweep. Throws
// std::invalid_argument for a damping ratio that is not positive on the backbone.
struct BackboneBounds {
  double a_lo = 0.0, a_hi = 0.0;  // the knots' amplitude span [m]
  double f_lo = 0.0, f_hi = 0.0;  // [Hz]
  double z_lo = 0.0, z_hi = 0.0;
};
BackboneBounds backbone_bounds(const NonlinearMode& mode);

// Every amplitude the force F holds at f_exc (roots of m a |D(a)| = F, ascending); each root's
// stability is d(m a |D|)/da > 0. Throws std::invalid_argument for a non-positive force or
// frequency, or a damping ratio that is not positive on the backbone. `bounds`: the mode's
// backbone_bounds (computed here when absent).
std::vector<double> amplitudes_at_force(const NonlinearMode& mode, double force, double f_exc_hz,
                                        const std::optional<BackboneBounds>& bounds = std::nullopt);

// The stable amplitude a stepped sine reaches at (F, f_exc) from the point before (its amplitude;
// nullopt: from rest, the smallest), the nearest in log a; with its sensitivities.
ModalPoint stepped_response(const NonlinearMode& mode, double force, double f_exc_hz,
                            std::optional<double> previous_amplitude,
                            const std::optional<BackboneBounds>& bounds = std::nullopt);

}  // namespace bb
