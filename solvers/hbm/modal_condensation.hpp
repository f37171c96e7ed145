// The dynamic stiffness D(w) = K + i w C - w^2 M condensed onto the contact DOFs by modal
// superposition, for the models whose damping is diagonal in the undamped modes of (K, M) (modal
// or Rayleigh damping; a rigid damper without damping of its own). With M-orthonormal modes Phi,
//   D(w)^-1 = Phi diag(1 / (lambda_r - w^2 + i w c_r)) Phi^T,
// and the Schur complement D_cc - D_co D_oo^-1 D_oc is the inverse of the contact block of D^-1,
// the receptance H_cc = Phi_c diag(...) Phi_c^T: a |c| x |c| inverse per frequency instead of a
// factorization of the other DOFs (on Table XI a third of the sweep's time went to the latter,
// the continuation condensing three times per evaluation). Exact up to rounding; for w > 0 only,
// since rigid-body modes (the damper's, lambda = 0) leave D(0) singular.
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <vector>

#include "friction/friction_system.hpp"

namespace bb::hbm {

// The condensation at one frequency, with the interface of friction::Condensation<complex>.
class ModalCondensation {
 public:
  using Vector = Eigen::VectorXcd;
  struct Load {
    Vector contact;  // H_cc^-1 (D^-1 f)_c: the condensed load
    Vector other;    // (D^-1 f)_o
  };

  // H_cc's reciprocal condition number in the 1-norm, 1 / (|H_cc| |H_cc^-1|), exact from the
  // inverse the condensation forms anyway (the LU's estimate cost as much as the 9 x 9 LU itself).
  double rcond() const { return rcond_; }
  const Eigen::MatrixXcd& reduced() const { return reduced_; }
  Load condense(const Vector& f) const;
  // x_o = (D^-1 f)_o + H_oc g, g = H_cc^-1 x_c - load.contact the force the contacts carry.
  Vector recover(const Load& load, const Vector& x_c) const;

 private:
  friend class ModalBasis;
  const class ModalBasis* basis_ = nullptr;
  Eigen::VectorXcd modal_;  // 1 / (lambda_r - w^2 + i w c_r)
  double rcond_ = 0.0;
  Eigen::MatrixXcd reduced_;
};

class ModalBasis {
 public:
  // None when K, M or C is not symmetric, M not positive definite, the eigensolver fails, or C
  // is not diagonal in the modes (an off-diagonal modal term above 1e-9 of the largest): the
  // caller then factorizes D_oo.
  static std::optional<ModalBasis> of(const friction::FrictionModel& model, const std::vector<Eigen::Index>& contact,
                                      const std::vector<Eigen::Index>& other);
  // w > 0.
  ModalCondensation at(double w) const;

 private:
  friend class ModalCondensation;
  std::vector<Eigen::Index> contact_, other_;
  Eigen::MatrixXd phi_c_, phi_o_;  // rows: contact / other DOFs; columns: modes
  Eigen::VectorXd lambda_, damping_;
};

}  // namespace bb::hbm
