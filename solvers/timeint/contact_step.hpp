// One implicit step of a point friction contact in the time domain: the predictor-corrector slider
// of thesis Table XII (section 3.4.2.1, eqs 3.44-3.48) evaluated on the rows of an
// friction::ContactElement, with the consistent tangent a Newton iteration needs. Units: SI.
//
// The law is the contact's (friction/friction_law.hpp), one step per call; for Jenkins,
// friction::jenkins_step (friction/jenkins.hpp): Table XII's s* = s - t2
// (eq 3.44) is the slider position w relative to body 2, t1 - t2 the relative tangential
// displacement u, and
//   stick          : s*(1) = s*(0),               T = kt (u - s*(0))   (eq 3.46)
//   positive slip  : s*(1) = u - mu N / kt,       T = +mu N            (eqs 3.47-3.48)
//   negative slip  : s*(1) = u + mu N / kt,       T = -mu N
//   separation     : s*(1) = u,                   T = N = 0
// with N = max(N0 + kn v, 0) (eq 3.45 plus the preload N0 of contact/). Here u = a_t . q -
// tangential_offset and v = a_n . q, the conventions of hbm/friction_system.hpp: T and N resist
// u and v, so the contact acts on the model DOFs with -(a_t^T T + a_n^T N).
//
// Why this is an implicit (backward) update: the slider is advanced from its converged position at
// the start of the step straight to the trial displacement at the end, so the forces at the end of
// the step are a function of the end displacements only (plus the old slider), and a Newton
// iteration on those displacements sees a piecewise-linear law with the tangent below.
#pragma once
#include <Eigen/Dense>

#include "friction/friction_system.hpp"

namespace bb::timeint {

// Derivatives of (T, N) with respect to (u, v) in the state reached (the consistent tangent of the
// return map): stick dT/du = kt, dN/dv = kn; slip dT/du = 0, dT/dv = +-mu kn, dN/dv = kn; lift-off
// all zero. dN/du is always zero.
struct ContactTangent {
  double dt_du = 0.0, dt_dv = 0.0, dn_dv = 0.0;
};

// One contact's kinematics and forces at one instant.
struct ContactSample {
  double u = 0.0;           // a_t . q - tangential_offset [m]
  double v = 0.0;           // a_n . q [m], > 0 presses
  double tangential = 0.0;  // T [N]
  double normal = 0.0;      // N [N], >= 0
  double slider = 0.0;      // w = s* after the step [m]
  friction::ContactState state = friction::ContactState::stick;
  ContactTangent tangent{};  // the law's, in the state reached
};

// Table XII for one contact: the slider at the start of the step, the displacements q at its end.
ContactSample contact_step(const friction::ContactElement& contact, double slider_before, const Eigen::VectorXd& q);

}  // namespace bb::timeint
