// Point friction contact with variable normal load: the 1D Jenkins (elastic-Coulomb) slider of
// thesis section 3.3.2.5, eqs 3.28-3.29 and Table X, and its 2D form (two uncoupled sliders
// sharing one normal load, the thesis's choice after Zucca, Fabbro, Gola 2012). Units: SI.
//
// Sign conventions. u is the relative tangential displacement of the two bodies, v the relative
// normal displacement, counted positive when it PRESSES the bodies together (so v > 0 raises the
// normal load and v < -N0 / kn opens the contact). N >= 0 is the normal load, T the tangential
// force carried by the tangential spring, T = kt (u - w): it has the sign of u - w, i.e. it is the
// force that resists u (a restoring force on the body whose displacement is u).
#pragma once
#include <Eigen/Dense>

#include <array>

namespace bb::friction {

// Parameters of one contact point, shared by every friction law here (friction/friction_law.hpp):
// the normal spring and preload, the stuck tangential stiffness, the Coulomb coefficient. Every
// value must be finite; kt > 0 (the slider position is recovered from T / kt in slip), kn >= 0
// (kn = 0 keeps N = N0), mu >= 0, n0 >= 0.
struct PointParameters {
  double kn = 0.0;  // normal contact stiffness [N/m]
  double kt = 0.0;  // tangential contact stiffness [N/m]
  double mu = 0.0;  // friction coefficient [-]
  double n0 = 0.0;  // static normal preload at v = 0 [N]
};

// Throws std::invalid_argument naming the offending value.
void validate(const PointParameters& p);

// Table X. slip_positive: T = +mu N and the slider moves towards +u (sgn w' = +1 in eq 3.29).
enum class ContactState { stick, slip_positive, slip_negative, lift_off };

const char* state_name(ContactState s);

struct JenkinsStep {
  double tangential = 0.0;  // T [N]
  double normal = 0.0;      // N [N], never negative
  double slider = 0.0;      // w after the step [m]
  ContactState state = ContactState::stick;
};

// One step of the slider from its position `slider` (w before the step) to the new relative
// displacements (u, v). Eq 3.28: N = max(N0 + kn v, 0). Then, with the trial force T* = kt (u - w):
//  - N == 0: lift-off, T = 0 and w = u. The slider follows the tangential motion while the contact
//    is open, so the contact re-sticks with zero tangential force when it closes again: the
//    standard choice of the refined approach (Zucca, Firrone, Gola).
//  - |T*| < mu N: stick, T = T*, w unchanged.
//  - otherwise: slip, T = sgn(T*) mu N and w = u - T / kt, so that kt (u - w) = T again. The test is
//    Table X's, strict for stick: at |T*| == mu N both branches give the same T and w, and a
//    frictionless contact (mu N = 0) is then always slipping, with T = 0, w = u and a zero
//    derivative, never a stuck spring when u happens to equal w (its slip direction is nominal).
//    A slip with T* == 0 counts as positive.
// The step is the exact update for a relative displacement that moves monotonically from the old
// to the new (u, v) at constant N; a marching caller takes steps small enough for that to hold.
// Neither the parameters nor the finiteness of (u, v) are checked here (the law is called in inner
// loops): call validate() once and keep the inputs finite.
JenkinsStep jenkins_step(const PointParameters& p, double slider, double u, double v);

struct JenkinsStep2D {
  Eigen::Vector2d tangential = Eigen::Vector2d::Zero();  // (T1, T2) [N]
  double normal = 0.0;                                   // N [N]
  Eigen::Vector2d slider = Eigen::Vector2d::Zero();      // (w1, w2) after the step [m]
  std::array<ContactState, 2> state{ContactState::stick, ContactState::stick};
};

// 2D contact of thesis Fig 3.55: two 1D sliders along orthogonal tangential directions, each with
// its own Coulomb limit mu N, sharing the normal load. The directions are uncoupled: a consequence
// is that |T| may reach sqrt(2) mu N in diagonal slip, the price of the 1D cost per direction.
JenkinsStep2D jenkins_step_2d(const PointParameters& p, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
                              double v);

}  // namespace bb::friction
