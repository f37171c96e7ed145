#include "frf/receptance.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "common/errors.hpp"
#include "linalg/dense_eigen.hpp"

namespace bb {
namespace {

using Complex = std::complex<double>;

double hz(double omega_rad_s) { return omega_rad_s / (2.0 * std::numbers::pi); }

double norm1(const Eigen::MatrixXd& a) { return a.size() == 0 ? 0.0 : a.cwiseAbs().colwise().sum().maxCoeff(); }

void require_square(const Eigen::MatrixXd& a, Eigen::Index n, const char* what, const char* caller) {
  if (a.rows() != n || a.cols() != n)
    throw std::invalid_argument(
        fmt::format("{}: {} is {} x {}, expected {} x {}", caller, what, a.rows(), a.cols(), n, n));
}

}  // namespace

Eigen::MatrixXcd ModalReceptance::at(double omega_rad_s) const {
  const Eigen::Index modes = omega.size();
  if (zeta.size() != modes || shapes_out.cols() != modes || shapes_in.cols() != modes)
    throw std::invalid_argument(
        fmt::format("ModalReceptance: {} frequencies, {} damping ratios, {} and {} shape columns", modes, zeta.size(),
                    shapes_out.cols(), shapes_in.cols()));
  if (residual.size() != 0 && (residual.rows() != shapes_out.rows() || residual.cols() != shapes_in.rows()))
    throw std::invalid_argument(fmt::format("ModalReceptance: residual is {} x {}, expected {} x {}", residual.rows(),
                                            residual.cols(), shapes_out.rows(), shapes_in.rows()));
  if (!std::isfinite(omega_rad_s)) throw std::invalid_argument("ModalReceptance: frequency is not finite");

  const double w = omega_rad_s;
  Eigen::VectorXcd gain(modes);
  for (Eigen::Index r = 0; r < modes; ++r) {
    const double wr = omega[r];
    const Complex den(wr * wr - w * w, 2.0 * zeta[r] * wr * w);
    if (!(std::abs(den) > kSingularDynamicStiffness * (wr * wr + w * w)))
      throw SolverError(fmt::format("modal receptance: mode {} ({:.9g} Hz, zeta {}) is hit exactly at {:.9g} Hz", r + 1,
                                    hz(wr), zeta[r], hz(w)));
    gain[r] = 1.0 / den;
  }
  Eigen::MatrixXcd h = shapes_out.cast<Complex>() * gain.asDiagonal() * shapes_in.transpose().cast<Complex>();
  if (residual.size() != 0) h += residual.cast<Complex>();
  return h;
}

Eigen::MatrixXd residual_flexibility(const Eigen::MatrixXd& static_flexibility, const Eigen::MatrixXd& shapes_out,
                                     const Eigen::MatrixXd& shapes_in, const Eigen::VectorXd& omega) {
  if (shapes_out.cols() != omega.size() || shapes_in.cols() != omega.size() ||
      static_flexibility.rows() != shapes_out.rows() || static_flexibility.cols() != shapes_in.rows())
    throw std::invalid_argument("residual_flexibility: sizes of the flexibility, shapes and frequencies disagree");
  if (omega.size() > 0 && !(omega.minCoeff() > 0.0))
    throw std::invalid_argument(
        "residual_flexibility: every kept mode needs w_r > 0 (a rigid mode has no static flexibility)");
  const Eigen::VectorXd inverse_square = omega.array().square().inverse();
  return static_flexibility - shapes_out * inverse_square.asDiagonal() * shapes_in.transpose();
}

RayleighCoefficients fit_rayleigh(double omega1, double zeta1, double omega2, double zeta2) {
  if (!(omega1 > 0.0) || !(omega2 > 0.0) || !std::isfinite(omega1) || !std::isfinite(omega2))
    throw std::invalid_argument("fit_rayleigh: both frequencies must be finite and > 0");
  if (omega1 == omega2) throw std::invalid_argument("fit_rayleigh: the two frequencies must differ");
  // Cramer's rule on [1/(2 w1), w1/2; 1/(2 w2), w2/2] [alpha; beta] = [zeta1; zeta2].
  const double d = omega2 * omega2 - omega1 * omega1;
  return {.alpha = 2.0 * omega1 * omega2 * (zeta1 * omega2 - zeta2 * omega1) / d,
          .beta = 2.0 * (zeta2 * omega2 - zeta1 * omega1) / d};
}

Eigen::MatrixXd modal_damping_matrix(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass, double zeta) {
  return modal_damping_matrix(stiffness, mass, Eigen::VectorXd::Constant(stiffness.rows(), zeta));
}

Eigen::MatrixXd modal_damping_matrix(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass,
                                     const Eigen::VectorXd& zetas) {
  const Eigen::Index n = stiffness.rows();
  require_square(stiffness, n, "stiffness", "modal_damping_matrix");
  require_square(mass, n, "mass", "modal_damping_matrix");
  if (zetas.size() != n)
    throw std::invalid_argument(
        fmt::format("modal_damping_matrix: {} damping ratios for a model of {} DOFs", zetas.size(), n));
  if (!((zetas.array() >= 0.0).all()) || !zetas.allFinite())
    throw std::invalid_argument("modal_damping_matrix: zeta must be finite and >= 0");
  if (n == 0) return Eigen::MatrixXd(0, 0);

  // Eigen's generalized solver factors M by LLT without reporting a failure, so check M first.
  const Eigen::VectorXd mass_eigenvalues = symmetric_eigen(mass, false).values;
  if (!(mass_eigenvalues[0] > 1e-14 * mass_eigenvalues[n - 1]))
    throw SolverError(
        fmt::format("modal_damping_matrix: the mass matrix is not positive definite (eigenvalues {:.3g} .. {:.3g})",
                    mass_eigenvalues[0], mass_eigenvalues[n - 1]));
  const DenseEigen<double> modes = symmetric_eigen(stiffness, mass);
  if (!modes.ok) throw SolverError("modal_damping_matrix: the dense eigensolver did not converge");

  // Eigenvectors come mass-normalized (Phi^T M Phi = I), which the formula needs.
  const Eigen::VectorXd& lambda = modes.values;
  const double rigid = 1e-10 * lambda.cwiseAbs().maxCoeff();
  if (lambda[0] < -rigid)
    throw SolverError(
        fmt::format("modal_damping_matrix: the stiffness has a negative eigenvalue w^2 = {:.6g}", lambda[0]));
  Eigen::VectorXd modal(n);
  for (Eigen::Index r = 0; r < n; ++r) modal[r] = lambda[r] <= rigid ? 0.0 : 2.0 * zetas[r] * std::sqrt(lambda[r]);
  const Eigen::MatrixXd m_phi = mass * modes.vectors;
  const Eigen::MatrixXd c = m_phi * modal.asDiagonal() * m_phi.transpose();
  return 0.5 * (c + c.transpose());
}

Eigen::VectorXcd direct_response(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& damping,
                                 const Eigen::MatrixXd& mass, double omega_rad_s, const Eigen::VectorXcd& force) {
  const Eigen::Index n = stiffness.rows();
  require_square(stiffness, n, "stiffness", "direct_response");
  require_square(mass, n, "mass", "direct_response");
  if (damping.size() != 0) require_square(damping, n, "damping", "direct_response");
  if (force.size() != n)
    throw std::invalid_argument(
        fmt::format("direct_response: force has {} entries, the model {} DOFs", force.size(), n));
  if (!std::isfinite(omega_rad_s)) throw std::invalid_argument("direct_response: frequency is not finite");
  const double w = omega_rad_s;

  Eigen::MatrixXcd d = (stiffness - w * w * mass).cast<Complex>();
  if (damping.size() != 0) d += Complex(0.0, w) * damping.cast<Complex>();
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(d);
  // Eigen's rcond() reports 1 for a zero pivot, and any 1 x 1 matrix has rcond 1: test the pivots
  // and measure the conditioning against the terms that cancel at resonance instead.
  const double scale = norm1(stiffness) + std::abs(w) * norm1(damping) + w * w * norm1(mass);
  const Eigen::VectorXcd pivots = lu.matrixLU().diagonal();
  double relative = 0.0;
  if (scale > 0.0 && (pivots.array().abs() > 0.0).all())
    relative = lu.rcond() * d.cwiseAbs().colwise().sum().maxCoeff() / scale;
  Eigen::VectorXcd x;
  if (relative >= kSingularDynamicStiffness) x = lu.solve(force);
  if (!(relative >= kSingularDynamicStiffness) || !x.allFinite())
    throw SolverError(
        fmt::format("direct_response: the dynamic stiffness is singular at {:.9g} Hz (reciprocal condition "
                    "{:.2e} relative to |K| + w|C| + w^2|M|): an undamped resonance?",
                    hz(w), relative));
  return x;
}

}  // namespace bb
