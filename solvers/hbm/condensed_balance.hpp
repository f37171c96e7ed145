// The harmonic balance of a friction system (hbm/friction_system.hpp) condensed onto its contact
// DOFs: thesis eqs 3.10-3.35 with H harmonics, static and dynamic balance solved together. Units: SI.
//
// Per harmonic h the linear part is condensed exactly onto the contact DOFs c by the Schur
// complement D~_h = D_cc - D_co D_oo^-1 D_oc of D_h = K + i h omega C - (h omega)^2 M (the inverse of
// the receptance r^(C,C) of eq 3.24, without ever forming it), so the nonlinear system has
// |c| (2H + 1) unknowns:
//   R(x, omega) = L(omega) x + g(x) - b(omega) = 0,
// L block-diagonal per harmonic, g the contact forces by the AFT (friction/aft.hpp). Requirement:
// D_h,oo must be invertible, i.e. the model with its contact DOFs clamped has no rigid-body mode
// (K_oo nonsingular, checked: std::invalid_argument) and is not driven exactly at an undamped
// resonance (reported as a failed solve). K_cc itself may be singular: a damper held only by its
// contacts is fine, since its DOFs are all contact DOFs and the contact stiffness closes the static
// balance; no ground spring is added anywhere.
//
// Unknown layout: x[j * nc + i] is real harmonic coefficient j (layout of aft.hpp: [c0, a1, b1, ...,
// aH, bH]) of contact DOF i (model DOF contact_dofs()[i]). A complex amplitude Z of harmonic h
// corresponds to a_h = Re Z, b_h = -Im Z (Re(Z e^{i h theta}) = a cos + b sin).
#pragma once
#include <Eigen/Dense>

#include <complex>
#include <limits>
#include <optional>
#include <vector>

#include "friction/aft.hpp"
#include "friction/friction_system.hpp"
#include "hbm/modal_condensation.hpp"

namespace bb::hbm {

// A partial-pivoting LU is singular for the harmonic balance's purposes when its reciprocal
// condition estimate is below this: the solve would amplify rounding by more than ~1e13.
inline constexpr double kSingularRcond = 1e-13;

struct HbmOptions {
  int harmonics = 1;  // H >= 1
  // AFT options; samples = 0 picks max(64, 16 (2H + 1)), enough for coefficient errors ~1e-4 on
  // stick-slip loops (the forces have kinks, their harmonics converge as 1 / n_t^2), or with
  // resolve_events max(32, 4 (2H + 1)), which only bracket the transitions.
  friction::AftOptions aft{};
  int max_iterations = 50;  // Newton iterations per solve (bounded: never hangs)
  // Converged when ||R|| <= tolerance * force_scale, R the condensed harmonic force balance [N] and
  // force_scale = ||f_static|| + ||F|| + sum_k (1 + mu_k) N0_k (see force_scale()).
  double tolerance = 1e-9;
  // Halvings of the Newton step before the secant and Levenberg-Marquardt steps are tried. A step
  // cut below 1/256 has met a kink that halving does not pass: on Table XI at H = 13, 73 % of the
  // residuals went to steps cut 9 to 30 times, for almost no progress.
  int max_backtracks = 8;
};

// The model prepared for repeated solves: validated, contact DOFs found, K_oo checked once.
// Throws std::invalid_argument on sizes, non-finite entries, invalid contact laws, no contact, or
// a singular K_oo (message says which requirement to meet).
class HarmonicBalance {
 public:
  HarmonicBalance(friction::FrictionModel model, HbmOptions options);

  const friction::FrictionModel& model() const { return model_; }
  const HbmOptions& options() const { return options_; }
  const std::vector<Eigen::Index>& contact_dofs() const { return system_.contact_dofs(); }
  const std::vector<Eigen::Index>& other_dofs() const { return system_.other_dofs(); }
  Eigen::Index unknowns() const;  // |c| (2H + 1)
  double force_scale() const { return force_scale_; }
  // ||R|| below which a solution counts as converged: options().tolerance * force_scale() [N].
  double residual_tolerance() const { return options_.tolerance * force_scale_; }
  // The AFT options every contact evaluation uses (samples resolved from options().aft).
  const friction::AftOptions& aft_options() const { return aft_; }

  // Condensed linear operator L(omega) (real layout, block-diagonal per harmonic) and load b(omega),
  // so that R(x, omega) = L x + g(x) - b. Returns nullopt when some D_h,oo is singular.
  struct Linear {
    Eigen::MatrixXd operator_;
    Eigen::VectorXd load;
  };
  std::optional<Linear> condense(double omega) const;

  // Contact forces g(x) on the contact DOFs and their exact Jacobian dg/dx, plus the AFT of each
  // contact (time histories, states, closure) at x.
  struct ContactForces {
    Eigen::VectorXd force;
    Eigen::MatrixXd jacobian;
    std::vector<friction::AftResult> contacts;
    bool closed = true;  // every slider loop closed
  };
  // With with_jacobian false the Jacobian is left empty (contact_jacobian assembles it later).
  ContactForces contact_forces(const Eigen::VectorXd& x, bool with_jacobian = true) const;
  // dg/dx from the AFT of every contact at x (ContactForces::contacts).
  Eigen::MatrixXd contact_jacobian(const std::vector<friction::AftResult>& contacts) const;

  // R(x) = L x + g(x) - b for the operator `linear` of some omega.
  struct Residual {
    Eigen::VectorXd residual;
    double norm = std::numeric_limits<double>::infinity();  // ||R|| when ok
    ContactForces forces;
    bool ok = false;  // x and R finite and every loop closed
  };
  Residual residual(const Linear& linear, const Eigen::VectorXd& x, bool with_jacobian = true) const;

  // Harmonic coefficients (rows: model DOFs, columns: the 2H + 1 coefficients) of every model DOF
  // for the contact-DOF solution x at omega: contact DOFs copied, the others recovered from
  // D_h,oo q_o = F_o - D_oc q_c (no contact force acts on them). Throws SolverError if D_h,oo is
  // singular at omega.
  Eigen::MatrixXd recover(const Eigen::VectorXd& x, double omega) const;

  // Linear solution with every contact replaced by springs (kn on a_n, and kt on a_t when `stuck`),
  // preload N0 kept in the static term; contact-DOF layout. nullopt when singular.
  std::optional<Eigen::VectorXd> linearized(double omega, bool stuck) const;

 private:
  friction::FrictionModel model_;
  HbmOptions options_;
  friction::FrictionSystem system_;
  friction::AftOptions aft_;
  double force_scale_ = 0.0;
  // D_0 = K does not depend on omega: condensed once. Harmonics h >= 1 by modal superposition
  // where the damping allows it (hbm/modal_condensation.hpp), else by factorizing D_h,oo.
  std::optional<friction::Condensation<std::complex<double>>> static_;
  std::optional<ModalBasis> modal_;
  // Per contact on c, the gap operators of a cyclic contact (hbm/cyclic_shift.hpp), built once for
  // H; empty for the others.
  struct CyclicGap {
    Eigen::MatrixXd tangential, normal;
  };
  std::vector<CyclicGap> cyclic_gaps_;

  // Calls use(condensation) with the condensation of harmonic h at omega (either kind).
  template <class Use>
  void with_condensation(int h, double omega, const Use& use) const;
};

}  // namespace bb::hbm
