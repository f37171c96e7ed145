// The exact flow of the friction system (hbm/friction_system.hpp) under a harmonic load, between and
// across its contact transitions. Units: SI; time as the phase theta = omega t.
//
// Between transitions every contact force is affine in q and the sliders w: stick T = kt (u - w),
// slip T = +-mu N, lift-off T = N = 0, N = N0 + kn v. With p = dq/dtheta the state z = (q, p, w, 1,
// cos theta, sin theta) obeys the linear system z' = A_m z of the contact modes m (the load is carried
// by the last three states), so z(theta + tau) = exp(A_m tau) z(theta) to rounding: no time-step
// error. A transition is a zero of a function linear in z (stick -> slip: |kt (u - w)| = mu N;
// slip -> stick: the slider's rate changes sign; lift-off and closing: N = 0), located by root finding
// on that exact motion inside pieces, from a sign change at their ends or a turning point of the
// function between them. A piece is `step` halved until the modes of A_m that turn by more than
// 1 rad in it carry at most 1e-9 of each event function (a stiff stuck contact rings; a reduced
// model has modes far above the excitation, mostly at rest), so that a function turns at most once.
//
// The sensitivity dz/dz0 (the monodromy matrix at the end of a period) is the product of the
// exponentials, with the sliders of contacts not stuck tied to q (they follow u) and one saltation
// term: a contact that closes sticks at the u it closes at, which moves with the closing phase. All
// other transitions keep the forces continuous, so they need none (a slip -> stick transition happens
// where the slider's rate is zero).
//
// Rigid stick (Coulomb's law, `rigid_stick`): a stuck contact holds u fixed instead of pulling on a
// spring kt (kt is then unused), so the stuck structure does not ring on kt and the flow agrees with
// Coulomb's law exactly. While contacts stick, the motion is that of the model constrained to
// a_t . q'' = 0 (the constraint forces are linear in z, so z' = A_m z still holds), a stuck contact
// slips once |T| reaches mu N, and a slipping one sticks where u' turns; the slider is u throughout.
// Sticking changes the acceleration at once, so the sensitivity takes the saltation
// I + (f+ - f-) g' / (g' f-) there; a contact that closes slips (N = 0 then) in the direction of u'.
#pragma once
#include <Eigen/Dense>

#include <map>
#include <string>
#include <vector>

#include "friction/friction_system.hpp"
#include "timeint/contact_step.hpp"

namespace bb::timeint {

// The state (q, p = dq/dtheta, sliders) at a phase, with each contact's mode.
struct FlowState {
  double theta = 0.0;
  Eigen::VectorXd q, p, w;
  std::vector<friction::ContactState> modes;
};

class PiecewiseFlow {
 public:
  // `model` validated (friction::validate_model) with an invertible mass; omega > 0 [rad/s].
  // Throws std::invalid_argument when M is singular. `step` [rad]: the sub-interval whose
  // exponentials are cached per combination of modes.
  // `rigid_stick`: Coulomb's stick (above) instead of the spring kt.
  PiecewiseFlow(const friction::FrictionModel& model, double omega_rad_s, double step, bool rigid_stick = false);

  Eigen::Index dofs() const { return n_; }
  Eigen::Index contacts() const { return nc_; }
  Eigen::Index state_size() const { return 2 * n_ + nc_; }  // (q, p, w)
  double omega() const { return omega_; }
  bool rigid_stick() const { return rigid_; }

  // The modes a state is in: lift-off where N <= 0, slip where |kt (u - w)| exceeds mu N (or sits on
  // it with the slider moving outwards), else stick; the sliders of contacts not stuck are set to
  // their value in that mode (w = u -+ mu N / kt, or u when open).
  void settle(FlowState& s) const;

  // d(q, p, w)/d(q, p, w) at a settled state: the identity, the rows of sliders not stuck tied to q
  // (with rigid stick every slider, and the rate of a stuck contact's u taken out of p).
  Eigen::MatrixXd start_jacobian(const FlowState& settled) const;

  // Advances a settled `s` to phase theta_end, locating every transition, and, when `jacobian` is
  // not null, carries d(q, p, w)/d(start) along (state_size() rows). With `extremes` (one entry per
  // `watch` DOF), each entry becomes the largest of itself and |q_d| over the interval, the extremes
  // of q_d located where dq_d/dtheta changes sign. A failure (more than max_events transitions,
  // counted in `events` across calls) leaves the state where it stopped; more than kMaxPieces pieces
  // (counted in `pieces`) throws SolverError naming the cap.
  struct Advance {
    int events = 0;
    long pieces = 0;
    std::vector<char> switched;  // per contact: some transition passed
    std::string failure;
  };
  // With `fourier` (one row per `watch` DOF, 2 H + 1 columns), the integrals of q_d, q_d cos(h theta)
  // and q_d sin(h theta) over the interval are added to columns 0, 2 h - 1 and 2 h: in closed form
  // on each piece by the modes of its generator, else by 8-point Gauss-Legendre on the piece.
  // The pieces one Advance log may take: a stiffness or a force so large (kt = 1e90) that the flow
  // resolves its motion in pieces of 1e-40 rad would otherwise run until killed. The shipped cases
  // take at most a few thousand per period.
  static constexpr long kMaxPieces = 1L << 20;
  void advance(FlowState& s, double theta_end, Eigen::MatrixXd* jacobian, int max_events, Advance& log,
               const std::vector<Eigen::Index>& watch = {}, Eigen::VectorXd* extremes = nullptr,
               Eigen::MatrixXd* fourier = nullptr) const;

  const Eigen::RowVectorXd& tangential(Eigen::Index k) const {
    return model_.contacts[static_cast<size_t>(k)].tangential;
  }

  // Contact k's kinematics and forces in state s (the conventions of timeint/contact_step.hpp).
  ContactSample sample(const FlowState& s, Eigen::Index k) const;

 private:
  // Event function of contact k in a mode as a row over z (> 0: the transition has happened).
  struct Event {
    Eigen::Index contact;
    friction::ContactState next;
    Eigen::RowVectorXd row;
  };
  Eigen::VectorXd pack(const FlowState& s) const;
  void unpack(const Eigen::VectorXd& z, FlowState& s) const;
  // `stuck_force`: with rigid stick, the row over z of each contact's constraint force T (empty rows
  // for contacts not stuck).
  std::vector<Event> events(const std::vector<friction::ContactState>& modes,
                            const std::vector<Eigen::RowVectorXd>& stuck_force) const;
  bool rigid(friction::ContactState m) const { return rigid_ && m == friction::ContactState::stick; }
  // With rigid stick, contact k held in state s with the others' modes: stick where its constraint
  // force is within mu N, else the slip that force drives.
  friction::ContactState held_or_slipping(const FlowState& s, Eigen::Index k) const;
  void rigid_constraints(const std::vector<friction::ContactState>& modes, Eigen::MatrixXd& a,
                         std::vector<Eigen::RowVectorXd>& stuck_force) const;
  // G: the tangential rows of the rigidly stuck contacts (their indices in `stuck`).
  Eigen::MatrixXd stuck_rows(const std::vector<friction::ContactState>& modes, std::vector<Eigen::Index>& stuck) const;
  Eigen::MatrixXd stuck_projection(const std::vector<friction::ContactState>& modes) const;  // of p
  void tie_sliders(FlowState& s, Eigen::MatrixXd* jacobian) const;
  // Contact ev.contact's transition at s, reached in the mode of generator a: its new mode, with the
  // sensitivity's saltation where the state or the acceleration jumps.
  void switch_contact(FlowState& s, const Event& ev, const Eigen::MatrixXd& a, Eigen::MatrixXd* jacobian) const;
  template <class TraceOf>
  void extremes_in_piece(const Eigen::MatrixXd& a, const Eigen::VectorXd& z0, const Eigen::VectorXd& z1, double tau,
                         const std::vector<Eigen::Index>& watch, Eigen::VectorXd& extremes, const TraceOf& trace) const;
  double algebraic_slider(const FlowState& s, Eigen::Index k, friction::ContactState m) const;
  Eigen::RowVectorXd slider_row(Eigen::Index k, friction::ContactState m) const;  // d w_k / dq in mode m

  friction::FrictionModel model_;
  double omega_, step_;
  bool rigid_;
  Eigen::Index n_, nc_, size_;  // DOFs, contacts, augmented size 2n + nc + 3
  Eigen::MatrixXd mass_inverse_;
  struct Generator {
    Eigen::MatrixXd a;
    // Without a usable modal basis (spectral false), pieces of at most 1 rad of the fastest motion.
    double piece = 0.0;
    Eigen::MatrixXd piece_exponential;                // exp(a piece)
    mutable std::map<int, Eigen::MatrixXd> halvings;  // exp(a step / 2^k)
    std::vector<Event> events;
    std::vector<Eigen::RowVectorXd> stuck_force;  // rigid stick: T of each stuck contact over z
    // a = V diag(lambda) V^-1 where V is well conditioned: event functions then cost O(size) a value.
    Eigen::VectorXcd lambda;                 // eigenvalues
    Eigen::MatrixXcd vectors;                // V
    std::vector<Eigen::RowVectorXcd> modal;  // each event's row times V
    Eigen::PartialPivLU<Eigen::MatrixXcd> basis;
    bool spectral = false;
    double basis_rcond = 0.0;  // the modal closed forms of the Fourier integrals need it well above 1e-12
  };
  const Generator& mode_data(const std::vector<friction::ContactState>& modes) const;
  int halvings(const Generator& mode, const Eigen::VectorXcd& coordinates) const;  // of step, for a piece
  mutable std::map<std::vector<friction::ContactState>, Generator> generators_;
};

}  // namespace bb::timeint
