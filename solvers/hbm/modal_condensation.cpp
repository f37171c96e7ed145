#include "hbm/modal_condensation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "linalg/dense_eigen.hpp"

namespace bb::hbm {

namespace {

using Index = Eigen::Index;

bool symmetric(const Eigen::MatrixXd& a) {
  return (a - a.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * std::max(a.cwiseAbs().maxCoeff(), 1e-300);
}

}  // namespace

std::optional<ModalBasis> ModalBasis::of(const friction::FrictionModel& model, const std::vector<Index>& contact,
                                         const std::vector<Index>& other) {
  const Eigen::MatrixXd& k = model.stiffness;
  const Eigen::MatrixXd& m = model.mass;
  const Eigen::MatrixXd c = model.damping.size() > 0 ? model.damping : Eigen::MatrixXd::Zero(k.rows(), k.cols());
  if (k.rows() == 0 || !symmetric(k) || !symmetric(m) || !symmetric(c)) return std::nullopt;
  if (Eigen::LLT<Eigen::MatrixXd>(m).info() != Eigen::Success) return std::nullopt;
  const DenseEigen<double> eig = symmetric_eigen(k, m);
  if (!eig.ok) return std::nullopt;
  const Eigen::MatrixXd& phi = eig.vectors;  // M-orthonormal
  const Eigen::MatrixXd modal_c = phi.transpose() * c * phi;
  const double largest = modal_c.cwiseAbs().maxCoeff();
  const Eigen::MatrixXd off = modal_c - Eigen::MatrixXd(modal_c.diagonal().asDiagonal());
  if (largest > 0.0 && off.cwiseAbs().maxCoeff() > 1e-9 * largest) return std::nullopt;
  ModalBasis b;
  b.contact_ = contact;
  b.other_ = other;
  b.phi_c_ = phi(contact, Eigen::all);
  b.phi_o_ = phi(other, Eigen::all);
  b.lambda_ = eig.values;
  b.damping_ = modal_c.diagonal();
  return b;
}

ModalCondensation ModalBasis::at(double w) const {
  ModalCondensation out;
  out.basis_ = this;
  out.modal_.resize(lambda_.size());
  for (Index r = 0; r < lambda_.size(); ++r)
    out.modal_[r] = 1.0 / std::complex<double>(lambda_[r] - w * w, w * damping_[r]);
  const Eigen::MatrixXcd receptance = (phi_c_ * out.modal_.asDiagonal()) * phi_c_.transpose();
  if (receptance.size() == 0) {  // no contact DOF: nothing to invert
    out.reduced_ = receptance;
    out.rcond_ = std::numeric_limits<double>::infinity();
    return out;
  }
  out.reduced_ = Eigen::PartialPivLU<Eigen::MatrixXcd>(receptance).inverse();
  const auto norm1 = [](const Eigen::MatrixXcd& a) { return a.cwiseAbs().colwise().sum().maxCoeff(); };
  const double product = norm1(receptance) * norm1(out.reduced_);
  out.rcond_ = std::isfinite(product) && product > 0.0 ? 1.0 / product : 0.0;
  return out;
}

ModalCondensation::Load ModalCondensation::condense(const Vector& f) const {
  const ModalBasis& b = *basis_;
  const Vector modal_load =
      modal_.cwiseProduct(b.phi_c_.transpose() * f(b.contact_) + b.phi_o_.transpose() * f(b.other_));
  Load load;
  load.contact = reduced_ * (b.phi_c_ * modal_load);
  load.other = b.phi_o_ * modal_load;
  return load;
}

ModalCondensation::Vector ModalCondensation::recover(const Load& load, const Vector& x_c) const {
  const ModalBasis& b = *basis_;
  const Vector g = reduced_ * x_c - load.contact;
  return load.other + b.phi_o_ * modal_.cwiseProduct(b.phi_c_.transpose() * g);
}

}  // namespace bb::hbm
