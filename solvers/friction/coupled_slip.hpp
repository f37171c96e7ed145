// The 2D contact with coupled tangential slip (thesis section 3.3.2.5: the most complete point
// model, left out there for its cost): one slider w in the tangent plane, a circular Coulomb limit
// |T| <= mu N over both tangential directions, variable normal load N = max(N0 + kn v, 0) and
// lift-off. Where the thesis's uncoupled pair (friction/jenkins.hpp's jenkins_step_2d) lets |T|
// reach sqrt(2) mu N in a diagonal slip, this law slips along the trial force. Units: SI.
//
// Step (the radial return of plasticity, exact for a straight path at constant N): with the trial
// force T* = kt (u - w),
//   N == 0:         lift-off, T = 0, w = u;
//   |T*| < mu N:    stick, T = T*, w unchanged;
//   otherwise:      slip, T = mu N T* / |T*|, w = u - T / kt.
// Tangent in slip, n = T* / |T*|: dT/du = mu N kt / |T*| (I - n n^T), dT/dv = mu kn n.
// On a straight path (u along a fixed direction) it is the 1D Jenkins law exactly; on a circle of
// radius r at constant N it reaches |T| = mu N with the slider on the circle of radius
// sqrt(r^2 - (mu N / kt)^2) and dissipates mu N 2 pi sqrt(r^2 - (mu N / kt)^2) per cycle.
#pragma once
#include "friction/friction_law.hpp"

namespace bb::friction {

// The step alone (what the law's interface and its AFT march).
LawStep coupled_slip_step(const PointParameters& point, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
                          double v);

// The law behind friction/friction_law.hpp: two directions, the sampled AFT whatever
// options.resolve_events asks (its slip direction turns continuously: no finite set of events to
// locate), no law derivatives (asked for, they throw naming the law), no piecewise-linear form.
const std::shared_ptr<const FrictionLaw>& coupled_slip_law();

}  // namespace bb::friction
