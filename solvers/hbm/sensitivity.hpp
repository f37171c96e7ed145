// Exact parameter sensitivities of a converged harmonic-balance solution (hbm/fixed_frequency.hpp)
// by the implicit function theorem. Units: SI (a derivative carries the unit of its quantity over
// that of the parameter).
//
// At a solution R(x, p) = L(omega, p) x + g(x, p) - b(omega, p) = 0 at fixed omega,
//   dx/dp = -J^{-1} dR/dp,   J = L + dg/dx,
// one factorization of J for every parameter. L and b are Schur complements of the per-harmonic
// dynamic stiffness D_h = K + i h omega C - (h omega)^2 M onto the contact DOFs c, so with q the
// recovered harmonics of all DOFs and r_h = dD_h q_h - dF_h (full DOF set) the linear part of dR/dp
// is r_c - D_co D_oo^-1 r_o per harmonic (the D_oo^-1 derivative folds into q_o), and the non-contact
// DOFs follow from D_oo dq_o = -r_o - D_oc dq_c, the derivative of HarmonicBalance::recover. The
// contact part dg/dp comes from the AFT law derivatives (friction/aft.hpp, law_derivatives).
//
// Validity: the AFT map is piecewise smooth (each time sample sticks, slips or is open). These are
// the exact derivatives of the discrete map on the piece that holds the solution; a parameter change
// that moves a sample across a switch adds a jump of O(1 / n_t) that no derivative represents.
// The tangential offsets of the contacts are held fixed.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "friction/aft.hpp"
#include "friction/jenkins.hpp"
#include "hbm/condensed_balance.hpp"
#include "hbm/fixed_frequency.hpp"

namespace bb::hbm {

// Derivative of the model with respect to one scalar parameter p. Empty members are zero.
struct ModelDerivative {
  Eigen::MatrixXd mass, damping, stiffness;  // dM/dp, dC/dp, dK/dp (n x n)
  Eigen::VectorXd static_load;               // df_static/dp (n)
  Eigen::VectorXcd harmonic_load;            // dF/dp (n), complex amplitude at harmonic 1
  std::vector<Eigen::VectorXcd> higher_loads;  // at harmonics 2, 3, ... (FrictionModel::higher_loads)
  // One entry per contact: d(kn, kt, mu, n0)/dp in the fields of the same name; empty = none.
  std::vector<friction::PointParameters> laws;
};

// d/dp for p = one law parameter shared by every contact (the usual single-law model).
ModelDerivative law_derivative(const friction::FrictionModel& model, friction::LawParameter parameter);
// d/ds of the model with C replaced by s C, at s = 1 (dC/ds = C). For modal or proportional damping
// C = zeta C1 this is zeta d/dzeta: divide the sensitivities by zeta for d/dzeta.
ModelDerivative damping_scale_derivative(const friction::FrictionModel& model);
// d/ds of the model with the harmonic load F replaced by s F, at s = 1 (static load unchanged).
ModelDerivative excitation_scale_derivative(const friction::FrictionModel& model);
// d/d omega at omega: D_h = K + i h omega C - (h omega)^2 M changes as with dC = C / omega and
// dM = 2 M / omega (the friction laws are rate-independent, the loads fixed). Throws
// std::invalid_argument for a cyclic model, whose nodal diameters carry their own operators.
ModelDerivative frequency_derivative(const friction::FrictionModel& model, double omega);

// dx/dp in the contact-DOF harmonic layout of HarmonicBalance (unknowns() rows), one column per
// entry of `derivatives`. Throws SolverError when the solution is not converged or J is singular
// (e.g. a damper whose static tangential position is free, where dx/dp is not unique), and
// std::invalid_argument on sizes.
[[nodiscard]] Eigen::MatrixXd solution_sensitivity(const HarmonicBalance& system, const HbmSolution& solution,
                                                   const std::vector<ModelDerivative>& derivatives);

// d(harmonic coefficients of every model DOF)/dp: one n x (2H + 1) matrix per parameter, the layout
// of HarmonicBalance::recover. Same errors as solution_sensitivity.
[[nodiscard]] std::vector<Eigen::MatrixXd> response_sensitivity(const HarmonicBalance& system,
                                                                const HbmSolution& solution,
                                                                const std::vector<ModelDerivative>& derivatives);

// d|q_dof,1|/dp, the first-harmonic amplitude sqrt(a1^2 + b1^2) of model DOF `dof`, one entry per
// parameter. Throws std::invalid_argument when dof is out of range or the amplitude is zero (not
// differentiable there), otherwise as above.
[[nodiscard]] Eigen::VectorXd amplitude_sensitivity(const HarmonicBalance& system, const HbmSolution& solution,
                                                    const std::vector<ModelDerivative>& derivatives, Eigen::Index dof);

}  // namespace bb::hbm
