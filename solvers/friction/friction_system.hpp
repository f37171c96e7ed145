// The friction system every nonlinear solver shares (the harmonic balance of hbm/, the time
// integration and shooting of timeint/; neither depends on the other): a small linear model (dense
// M, C, K) with point friction contacts of variable normal load, each with its law
// (friction/friction_law.hpp: Jenkins by default; a Masing law of several sliders,
// friction/masing.hpp, arrives as several Jenkins contacts), and its exact condensation onto the
// DOFs the contacts touch.
// Units: SI.
//
// Equation of motion, q the model DOFs:
//   M q'' + C q' + K q + sum_k (a_t,k^T T_k + a_n,k^T N_k) = f_static + f(t),
// u_k = a_t,k . q and v_k = a_n,k . q the relative tangential and normal displacements of contact k
// (v > 0 presses, as in friction/jenkins.hpp), T_k and N_k the law's forces of contact k (N_k = max(N0 + kn v,
// 0) includes the preload N0). Sign convention: T and N are the forces that RESIST u and v, so the
// contact acts on the DOFs with -a_t^T T - a_n^T N (action = reaction: a contact joining DOF i with
// +1 and DOF j with -1 pushes them apart with N and drags them together with T). A contact with
// only +1 on one DOF ties that DOF to the ground.
//
// Condensation. The DOFs touched by any a_t or a_n are the contact DOFs c, the rest o. No contact
// force acts on o, so any linear operator A of the model (the dynamic stiffness D_h of harmonic h,
// thesis eqs 3.22-3.27; Newmark's effective stiffness K_eff) is condensed exactly onto c by the
// Schur complement
//   S = A_cc - A_co A_oo^-1 A_oc,   S x_c + g(x_c) = f_c - A_co y_o,   y_o = A_oo^-1 f_o,
// and o is recovered as x_o = y_o - (A_oo^-1 A_oc) x_c. Requirement: A_oo invertible (the model with
// its contact DOFs clamped is held); each solver checks rcond() against its own threshold.
#pragma once
#include <Eigen/Dense>

#include <complex>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "friction/friction_law.hpp"

namespace bb::friction {

// One point contact. Both rows have one entry per model DOF; zero entries leave a DOF untouched.
struct ContactElement {
  PointParameters point;          // kn, kt, mu, N0 (validated by friction::validate)
  Eigen::RowVectorXd tangential;  // a_t: u = a_t . q
  Eigen::RowVectorXd normal;      // a_n: v = a_n . q
  // The slider's rest position: u = a_t . q - tangential_offset enters the law, so a contact that
  // closed at a static seat (e.g. a damper pressed in by CF with no friction) carries no tangential
  // force there and a stuck contact stays continuous with one that starts to slip.
  double tangential_offset = 0.0;  // [m]
  // Cyclic symmetry (one sector of a tuned bladed disk in a travelling wave of inter-sector phase
  // phi): the contact also moves with the next sector, whose DOFs move as this sector's own shifted
  // in phase, q_next(theta) = q(theta + phi), so u = a_t . q(theta) + a_t,next . q(theta + phi) (and
  // v alike); the force on this sector is then -a_t^T T(theta) - a_t,next^T T(theta - phi), the
  // reaction the previous sector's contact puts on it. Only the harmonic balance solves such a
  // contact (in harmonic h the shift turns the coefficients by h phi). Empty rows: no next sector.
  Eigen::RowVectorXd tangential_next{}, normal_next{};
  double next_phase = 0.0;  // phi [rad]
  // The second tangential direction of a law of two (coupled slip): u_2 = a_t2 . q, its force
  // -a_t2^T T_2 on the DOFs; empty for a law of one. Not with a next sector.
  Eigen::RowVectorXd tangential_2{};
  std::shared_ptr<const FrictionLaw> law = jenkins_law();  // never null

  bool cyclic() const { return tangential_next.size() > 0 || normal_next.size() > 0; }
};

// One sector of a tuned cyclic structure cut through elastic material (a disk): in a travelling
// wave of engine order EO, harmonic h belongs to nodal diameter k = h EO mod N, and the sector's
// M, C, K for k are Hermitian (its right face follows its left one with the phase 2 pi k / N,
// cyclic/cyclic_reduction.hpp). They replace the model's real M, C, K in D_h for h >= 1; harmonic 0
// (k = 0) keeps the real ones. The DOFs are the same for every k (the contacts, loads and responses
// name them); a k with fewer internal coordinates pads them as decoupled unit springs without mass.
struct NodalDiameterOperators {
  Eigen::MatrixXcd mass, damping, stiffness;  // n x n; empty where no harmonic reaches k
};
struct CyclicLinearModel {
  int sectors = 0, engine_order = 0;
  std::vector<NodalDiameterOperators> diameters;  // k = 0 .. N-1; empty = the model is not cyclic

  bool empty() const { return diameters.empty(); }
  int diameter(int harmonic) const {
    return static_cast<int>((static_cast<long long>(harmonic) * engine_order) % sectors);
  }
  const NodalDiameterOperators& of_harmonic(int harmonic) const {
    return diameters[static_cast<size_t>(diameter(harmonic))];
  }
};

struct FrictionModel {
  Eigen::MatrixXd mass, damping, stiffness;  // n x n, dense; damping may be empty (C = 0)
  std::vector<ContactElement> contacts;      // at least one for the harmonic balance
  Eigen::VectorXd static_load;               // n [N]; empty = none (e.g. centrifugal force on the damper)
  Eigen::VectorXcd harmonic_load;            // n [N], complex amplitude at harmonic 1; empty = none
  // Harmonics 2, 3, ... of the excitation (a base motion's distortion), entry k at harmonic k + 2,
  // each n complex amplitudes [N]; empty = harmonic 1 alone. Not with nodal diameters.
  std::vector<Eigen::VectorXcd> higher_loads{};
  CyclicLinearModel nodal_diameters{};  // the harmonic balance only; empty = none
};

// The excitation's complex amplitudes at harmonic h >= 1 (zero above the last given), n entries.
Eigen::VectorXcd excitation_at(const FrictionModel& model, int harmonic);
// Multiplies every harmonic of the excitation by `factor` (a force or base level).
void scale_excitation(FrictionModel& model, double factor);

// D_h = K + i h w C - (h w)^2 M, with the nodal diameter's operators for h >= 1 where the model has
// them; hw = h w [rad/s].
Eigen::MatrixXcd dynamic_stiffness(const FrictionModel& model, int harmonic, double hw);

// Fills an empty C and empty loads with zeros (and a cyclic contact's empty next rows), then checks
// sizes, finiteness and every contact law of `model` (contacts may be empty); cyclic contacts only
// where `cyclic_allowed` (the harmonic balance), laws of two tangential directions only where
// `two_directions_allowed` (the harmonic balance: the time integration keeps one slider coordinate
// per contact). Throws std::invalid_argument, the message prefixed by `who`. Shared by the harmonic
// balance and the time integration.
void validate_model(FrictionModel& model, const std::string& who, bool cyclic_allowed = false,
                    bool two_directions_allowed = false);

// K with every contact replaced by its springs, kn on a_n and kt on a_t (the fully stuck limit, eq 3.51).
// A cyclic contact adds its own rows' springs only; the nodal diameters' operators are not used.
Eigen::MatrixXd stuck_stiffness(const FrictionModel& model);
// The same for harmonic h of a travelling wave: a cyclic contact's springs act on
// g = a + e^{i h phi} a_next and add kt g^H g (Hermitian), on the stiffness of harmonic h's nodal
// diameter where the model has them; equal to stuck_stiffness without either.
Eigen::MatrixXcd stuck_stiffness(const FrictionModel& model, int harmonic);

// One linear operator A condensed onto c (formulas above), A_oo factorized once (partial-pivoting
// LU). Scalar: double (time domain) or std::complex<double> (one harmonic).
template <class Scalar>
class Condensation {
 public:
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

  Condensation(const Matrix& a, const std::vector<Eigen::Index>& contact_dofs,
               const std::vector<Eigen::Index>& other_dofs);

  // Reciprocal condition estimate of A_oo's LU, taken once (a balance asks for it at every
  // evaluation); +inf when there is no o. Valid results need it above the caller's singularity
  // threshold.
  double rcond() const { return rcond_; }
  const Matrix& reduced() const { return reduced_; }  // S, |c| x |c|

  // A right-hand side f (all DOFs) split for the condensed solve.
  struct Load {
    Vector contact;  // f_c - A_co y_o
    Vector other;    // y_o = A_oo^-1 f_o
  };
  Load condense(const Vector& f) const;
  // x_o from x_c (the condensed solution) and the load it was solved with.
  Vector recover(const Load& load, const Vector& x_c) const;

 private:
  std::vector<Eigen::Index> contact_dofs_, other_dofs_;
  Eigen::Index other_ = 0;
  Eigen::PartialPivLU<Matrix> lu_oo_;
  double rcond_ = std::numeric_limits<double>::infinity();
  Matrix a_co_, static_modes_, reduced_;  // A_co, A_oo^-1 A_oc, S
};

extern template class Condensation<double>;
extern template class Condensation<std::complex<double>>;

// The contact/other split of a validated model and the contact rows restricted to c.
class FrictionSystem {
 public:
  explicit FrictionSystem(const FrictionModel& model);

  const std::vector<Eigen::Index>& contact_dofs() const { return contact_dofs_; }  // c, ascending
  const std::vector<Eigen::Index>& other_dofs() const { return other_dofs_; }      // o, ascending
  // The model's contacts with a_t and a_n restricted to c (entry i belongs to contact_dofs()[i]).
  const std::vector<ContactElement>& contacts_on_c() const { return contacts_on_c_; }

  template <class Scalar>
  Condensation<Scalar> condense(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& a) const {
    return Condensation<Scalar>(a, contact_dofs_, other_dofs_);
  }

 private:
  std::vector<Eigen::Index> contact_dofs_, other_dofs_;
  std::vector<ContactElement> contacts_on_c_;
};

}  // namespace bb::friction
