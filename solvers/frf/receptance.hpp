// Linear receptances of a damped structure, thesis eqs 3.32 and 3.37-3.39.
#pragma once
#include <Eigen/Dense>

#include <complex>

namespace bb {

// D(w) (or one modal denominator) counts as singular when its reciprocal condition number, measured
// against the parts that cancel at resonance (|K| + w |C| + w^2 |M|, or w_r^2 + w^2), is below this:
// the answer would then carry no correct digit. An undamped resonance hit exactly gives ~1e-16.
inline constexpr double kSingularDynamicStiffness = 1e-14;

// Modal superposition (eq 3.32): H(w) = sum_r phi_out,r phi_in,r^T / (w_r^2 - w^2 + 2 i zeta_r w_r w)
// (+ residual, a constant flexibility standing in for the truncated modes).
struct ModalReceptance {
  Eigen::VectorXd omega;       // w_r [rad/s], one per kept mode
  Eigen::VectorXd zeta;        // modal damping ratio per mode
  Eigen::MatrixXd shapes_out;  // mass-normalized shapes at the response DOFs (n_out x modes)
  Eigen::MatrixXd shapes_in;   // at the force DOFs (n_in x modes)
  Eigen::MatrixXd residual;    // n_out x n_in, or empty

  // n_out x n_in receptance [m/N] at w [rad/s]. Throws std::invalid_argument when the sizes
  // disagree and SolverError when w hits an undamped w_r (a rigid mode at w = 0 included).
  Eigen::MatrixXcd at(double omega_rad_s) const;
};

// Residual flexibility of the truncated modes: K^-1 (out, in) - sum_r phi_out,r phi_in,r^T / w_r^2.
// `static_flexibility` is K^-1 restricted to out x in; every w_r must be > 0 (std::invalid_argument).
Eigen::MatrixXd residual_flexibility(const Eigen::MatrixXd& static_flexibility, const Eigen::MatrixXd& shapes_out,
                                     const Eigen::MatrixXd& shapes_in, const Eigen::VectorXd& omega);

// Rayleigh damping C = alpha M + beta K with zeta = alpha / (2 w) + beta w / 2 at w1 and w2 (eqs 3.37-3.39).
struct RayleighCoefficients {
  double alpha = 0.0;  // [1/s]
  double beta = 0.0;   // [s]
};
// Throws std::invalid_argument unless w1, w2 > 0 and w1 != w2.
RayleighCoefficients fit_rayleigh(double omega1, double zeta1, double omega2, double zeta2);

// C = M Phi diag(2 zeta_r w_r) Phi^T M over every mode of the small dense model (K, M), one zeta for all.
// Rigid modes (w_r^2 <= 1e-10 max w^2) get no damping. Throws SolverError when M is not positive
// definite or K has a clearly negative eigenvalue, std::invalid_argument on sizes or zeta < 0.
Eigen::MatrixXd modal_damping_matrix(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass, double zeta);
// The same with zeta_r per mode, in ascending frequency (one per DOF of the model).
Eigen::MatrixXd modal_damping_matrix(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass,
                                     const Eigen::VectorXd& zetas);

// Direct solve of D(w) x = f, D = K + i w C - w^2 M, for small dense models; an empty `damping`
// means C = 0. Throws SolverError when D(w) is singular (an undamped resonance hit exactly, see
// kSingularDynamicStiffness), std::invalid_argument when the sizes disagree.
Eigen::VectorXcd direct_response(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& damping,
                                 const Eigen::MatrixXd& mass, double omega_rad_s, const Eigen::VectorXcd& force);

}  // namespace bb
