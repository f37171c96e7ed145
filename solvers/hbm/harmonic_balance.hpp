// Multi-DOF harmonic balance of a small linear model (dense M, C, K) with point Jenkins friction
// contacts of variable normal load (contact/jenkins_contact.hpp, contact/aft.hpp): thesis eqs
// 3.10-3.35 with H harmonics, static and dynamic balance solved together. Units: SI.
//
// Equation of motion, q the model DOFs:
//   M q'' + C q' + K q + sum_k (a_t,k^T T_k + a_n,k^T N_k) = f_static + Re(F e^{i omega t}),
// u_k = a_t,k . q and v_k = a_n,k . q the relative tangential and normal displacements of contact k
// (v > 0 presses, as in contact/), T_k and N_k the Jenkins forces of contact k (N_k = max(N0 + kn v,
// 0) includes the preload N0). Sign convention: T and N are the forces that RESIST u and v, so the
// contact acts on the DOFs with -a_t^T T - a_n^T N (action = reaction: a contact joining DOF i with
// +1 and DOF j with -1 pushes them apart with N and drags them together with T). A contact with
// only +1 on one DOF ties that DOF to the ground.
//
// Condensation (eqs 3.22-3.27 in dynamic-stiffness form). The DOFs touched by any a_t or a_n are the
// contact DOFs c, the rest o. Per harmonic h the linear part is condensed exactly onto c by the
// Schur complement D~_h = D_cc - D_co D_oo^-1 D_oc of D_h = K + i h omega C - (h omega)^2 M (the
// inverse of the receptance r^(C,C) of eq 3.24, without ever forming it), so the nonlinear system
// has |c| (2H + 1) unknowns. Requirement: D_h,oo must be invertible, i.e. the model with its contact
// DOFs clamped has no rigid-body mode (K_oo nonsingular, checked: std::invalid_argument) and is not
// driven exactly at an undamped resonance (reported as a failed solve). K_cc itself may be singular:
// a damper held only by its contacts is fine, since its DOFs are all contact DOFs and the contact
// stiffness closes the static balance; no ground spring is added anywhere.
//
// Unknown layout: x[j * nc + i] is real harmonic coefficient j (layout of aft.hpp: [c0, a1, b1, ...,
// aH, bH]) of contact DOF i (model DOF contact_dofs()[i]). A complex amplitude Z of harmonic h
// corresponds to a_h = Re Z, b_h = -Im Z (Re(Z e^{i h theta}) = a cos + b sin).
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contact/aft.hpp"
#include "contact/jenkins_contact.hpp"

namespace bb::hbm {

// One point contact. Both rows have one entry per model DOF; zero entries leave a DOF untouched.
struct ContactElement {
  contact::JenkinsParameters law;  // kn, kt, mu, N0 (validated by contact::validate)
  Eigen::RowVectorXd tangential;   // a_t: u = a_t . q
  Eigen::RowVectorXd normal;       // a_n: v = a_n . q
  // The slider's rest position: u = a_t . q - tangential_offset enters the law, so a contact that
  // closed at a static seat (e.g. a damper pressed in by CF with no friction) carries no tangential
  // force there and a stuck contact stays continuous with one that starts to slip.
  double tangential_offset = 0.0;  // [m]
};

struct HbmModel {
  Eigen::MatrixXd mass, damping, stiffness;  // n x n, dense; damping may be empty (C = 0)
  std::vector<ContactElement> contacts;      // at least one
  Eigen::VectorXd static_load;               // n [N]; empty = none (e.g. centrifugal force on the damper)
  Eigen::VectorXcd harmonic_load;            // n [N], complex amplitude at harmonic 1; empty = none
};

// Fills an empty C and empty loads with zeros, then checks sizes, finiteness and every contact
// law of `model` (contacts may be empty). Throws std::invalid_argument, the message prefixed by
// `who`. Shared by the harmonic balance and the time integration (time/newmark.hpp).
void validate_model(HbmModel& model, const std::string& who);

struct HbmOptions {
  int harmonics = 1;  // H >= 1
  // AFT options; samples = 0 picks max(64, 16 (2H + 1)) as contact/hbm_oscillator does.
  contact::AftOptions aft{};
  int max_iterations = 50;  // Newton iterations per solve (bounded: never hangs)
  // Converged when ||R|| <= tolerance * force_scale, R the condensed harmonic force balance [N] and
  // force_scale = ||f_static|| + ||F|| + sum_k (1 + mu_k) N0_k (see force_scale()).
  double tolerance = 1e-9;
  int max_backtracks = 30;  // halvings of the Newton step before the solve is declared failed
};

// The model prepared for repeated solves: validated, contact DOFs found, K_oo factorized once.
// Throws std::invalid_argument on sizes, non-finite entries, invalid contact laws, no contact, or
// a singular K_oo (message says which requirement to meet).
class HarmonicBalance {
 public:
  HarmonicBalance(HbmModel model, HbmOptions options);

  const HbmModel& model() const { return model_; }
  const HbmOptions& options() const { return options_; }
  const std::vector<Eigen::Index>& contact_dofs() const { return contact_dofs_; }
  Eigen::Index unknowns() const;  // |c| (2H + 1)
  double force_scale() const { return force_scale_; }
  // The AFT options every contact evaluation uses (samples resolved from options().aft).
  const contact::AftOptions& aft_options() const { return aft_; }

  // Condensed linear operator L(omega) (real layout, block-diagonal per harmonic) and load b(omega),
  // so that R(x, omega) = L x + g(x) - b. Returns false when some D_h,oo is singular.
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
    std::vector<contact::AftResult> contacts;
    bool closed = true;  // every slider loop closed
  };
  ContactForces contact_forces(const Eigen::VectorXd& x) const;

  // Harmonic coefficients (rows: model DOFs, columns: the 2H + 1 coefficients) of every model DOF
  // for the contact-DOF solution x at omega: contact DOFs copied, the others recovered from
  // D_h,oo q_o = F_o - D_oc q_c (no contact force acts on them). Throws SolverError if D_h,oo is
  // singular at omega.
  Eigen::MatrixXd recover(const Eigen::VectorXd& x, double omega) const;

  // Linear solution with every contact replaced by springs (kn on a_n, and kt on a_t when `stuck`),
  // preload N0 kept in the static term; contact-DOF layout. nullopt when singular.
  std::optional<Eigen::VectorXd> linearized(double omega, bool stuck) const;

 private:
  HbmModel model_;
  HbmOptions options_;
  std::vector<Eigen::Index> contact_dofs_, other_dofs_;
  Eigen::MatrixXd tangential_c_, normal_c_;  // a_t, a_n restricted to the contact DOFs, one row per contact
  contact::AftOptions aft_;
  double force_scale_ = 0.0;
};

struct HbmSolution {
  Eigen::VectorXd x;      // contact-DOF harmonics, layout above [m]
  double omega = 0.0;     // [rad/s]
  int iterations = 0;     // Newton iterations taken
  double residual = 0.0;  // ||R|| [N] (finite, or +inf when the start could not be evaluated)
  bool converged = false;
  std::string failure;  // why not converged (with |R| and omega); empty when converged
  std::vector<contact::AftResult> contacts;  // the AFT of each contact at x
};

// Newton-Raphson with backtracking line search (Armijo on ||R||) at fixed omega, Levenberg-
// Marquardt steps when backtracking fails. Starts from `initial` when given, then (if that fails)
// from the two linear limits (contacts stuck, or normal springs only), the better one first; each
// start gets options.max_iterations, `iterations` reports the total.
// Never throws on non-convergence: converged == false with a message; never returns NaN.
[[nodiscard]] HbmSolution solve_at_frequency(const HarmonicBalance& system, double omega_rad_s,
                                             const std::optional<Eigen::VectorXd>& initial = std::nullopt);

// Energy per cycle at a solution (J): excitation work = viscous + friction (+ normal, which is
// zero up to the AFT sampling for the elastic normal law). Uses the recovered harmonics of all DOFs.
struct CycleEnergy {
  double excitation = 0.0;  // integral of f . dq over one period
  double viscous = 0.0;     // integral of q'^T C q' dt
  double friction = 0.0;    // sum_k integral of T_k du_k
  double normal = 0.0;      // sum_k integral of N_k dv_k
};
CycleEnergy cycle_energy(const HarmonicBalance& system, const HbmSolution& solution);

// ---- Frequency continuation: tangent predictor + pseudo-arclength corrector in (x, omega). ----
// Known limit: R is only piecewise smooth (AFT samples switch between stick, slip and lift-off).
// Where the path meets a kink at a large angle (grazing of a stiff impact, kn >> k) the corrector
// can stall on the kink; after the step falls below min_step a few larger steps over it are tried,
// and if they fail the result says so (converged == false, with omega and |R|).

struct ContinuationProgress {
  int point = 0;           // index of the point just accepted
  double omega = 0.0;      // [rad/s]
  double amplitude = 0.0;  // max over contact DOFs of the first-harmonic amplitude [m]
  double step = 0.0;       // scaled arclength step used
  int iterations = 0;      // corrector iterations
};

struct ContinuationOptions {
  double omega_start = 0.0, omega_end = 0.0;  // [rad/s], > 0; either order
  // Arclength is measured in scaled variables (x / x_ref, omega / omega_start), x_ref the norm of the
  // harmonic part of the first solution (or amplitude_scale when > 0).
  double amplitude_scale = 0.0;
  double initial_step = 0.02;
  double min_step = 1e-6;   // below this after shrinking the continuation stops as failed
  double max_step = 0.5;
  double grow = 1.5;        // step factor after a corrector that converged in <= easy_iterations
  double shrink = 0.5;      // step factor after a failed corrector
  int easy_iterations = 4;
  int max_corrector_iterations = 25;
  int max_points = 5000;    // hard cap, then failure
  std::optional<Eigen::VectorXd> initial = std::nullopt;  // guess for the first point (e.g. from a static pre-solve)
  std::function<void(const ContinuationProgress&)> progress;  // called per accepted point; may be empty
};

struct ContinuationPoint {
  double omega = 0.0;
  Eigen::VectorXd x;
  double residual = 0.0;  // ||R|| [N]
  int iterations = 0;
  double step = 0.0;      // scaled arclength from the previous point (0 for the first)
  double tangent_omega = 0.0;  // d(omega / omega_start)/ds at the point; its sign changes at a fold
};

struct ContinuationResult {
  std::vector<ContinuationPoint> points;
  bool converged = false;   // reached omega_end
  std::string failure;      // with |R| and omega when not converged
  int turning_points = 0;   // sign changes of d omega / ds along the path
  int corrector_iterations = 0, rejected_steps = 0;
  int jumps = 0;  // points reached by stepping over a kink after the step fell below min_step
  double amplitude_scale = 0.0;
};

[[nodiscard]] ContinuationResult continue_in_frequency(const HarmonicBalance& system,
                                                       const ContinuationOptions& options);

}  // namespace bb::hbm
