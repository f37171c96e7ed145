// Stability of a periodic solution of the harmonic balance by Hill's method: a perturbation
// p(t) e^(lambda t) of the motion, p periodic and expanded in the same H harmonics, satisfies the
// quadratic eigenproblem (Delta0 + lambda Delta1 + lambda^2 Delta2) P = 0 with, per DOF block,
//   Delta0 = dR/dq (the balance's full Jacobian: nabla^2 x M + nabla x C + I x K + dG/dq),
//   Delta1 = 2 nabla x M + I x C,   Delta2 = I x M,
// nabla the time derivative on the real harmonic coefficients [c0, a1, b1, ...] (a_h' = h omega b_h,
// b_h' = -h omega a_h). Its 2 n (2H + 1) eigenvalues are the Floquet exponents repeated at
// shifts of i k omega; the 2 n with the smallest |Im| are kept (the usual sorting; the copies at
// the edge of the harmonic range have spoiled real parts). Stable when every kept exponent within
// the band the H harmonics resolve, |Im| <= (H + 1/2) omega, has Re <= marginal_tolerance,
// unstable when one has more. A kept exponent beyond the band (e.g. a damper's contact modes at kHz
// under an excitation at 175 Hz with H = 1) has a real part the truncation spoils: growth there
// makes the verdict unknown (`unresolved`), not unstable. Modes far above the band may not be kept
// at all: Hill's method with few harmonics does not assess them.
// The contact forces enter by their AFT Jacobian: for friction, whose slider states carry memory,
// this is the linearization about the converged cycle, the common practice (Krack & Gross 2019,
// "Harmonic Balance for Nonlinear Vibration Problems", ch. 5), not a rigorous Floquet analysis.
#pragma once
#include <Eigen/Dense>

#include <string>

#include "hbm/condensed_balance.hpp"

namespace bb::hbm {

struct HillStability {
  bool ok = false;             // the eigenproblem was solved
  std::string failure;         // why not
  bool stable = false;         // every kept exponent has Re <= marginal_tolerance, none unresolved
  double max_real = 0.0;       // the largest real part of the kept exponents within the band [1/s]
  std::string unresolved;      // non-empty: growth beyond the resolved band (the verdict is unknown)
  double unresolved_real = 0.0;
  Eigen::VectorXcd exponents;  // the 2 n kept exponents, largest real part first [1/s]

  bool growing = false;        // an exponent within the band has Re > marginal_tolerance: unstable

  // 1 stable, 0 unstable, NaN unknown (not solved, or growth only beyond the resolved band).
  double verdict() const;
};

// Re lambda above this counts as growth: round-off of an undamped (marginal) exponent stays below.
double marginal_tolerance(double omega);

// Floquet exponents of the solution x (contact-DOF harmonics of `system`) at omega [rad/s].
// Never throws for a numerical failure (ok = false, with the reason).
HillStability hill_stability(const HarmonicBalance& system, const Eigen::VectorXd& x, double omega);

}  // namespace bb::hbm
