// The harmonic balance at one frequency: R(x, omega) = 0 of hbm/condensed_balance.hpp solved by
// damped Newton (eq 3.35, linalg/damped_newton.hpp) with the exact AFT Jacobian. Units: SI.
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

#include "friction/aft.hpp"
#include "hbm/condensed_balance.hpp"

namespace bb {
class ChordFactorization;  // linalg/damped_newton.hpp
}  // namespace bb

namespace bb::hbm {

// Where a solve's Newton iteration started (solve_at_frequency tries them in turn).
enum class HbmStart {
  initial,  // the caller's guess
  stuck,    // the linear limit with every contact stuck (kn and kt springs)
  sliding,  // the linear limit with normal springs only
  zero,     // x = 0 (no guess and no usable linear limit)
};

struct HbmSolution {
  Eigen::VectorXd x;      // contact-DOF harmonics, layout of condensed_balance.hpp [m]
  double omega = 0.0;     // [rad/s]
  int iterations = 0;     // Newton iterations taken
  double residual = 0.0;  // ||R|| [N] (finite; the largest double when the start could not be evaluated)
  bool converged = false;
  std::string failure;                        // why not converged (with |R| and omega); empty when converged
  std::vector<friction::AftResult> contacts;  // the AFT of each contact at x
  HbmStart start = HbmStart::initial;         // the start x was reached from
};

// Newton-Raphson with backtracking line search (Armijo on ||R||) at fixed omega, Levenberg-
// Marquardt steps when backtracking fails, minimum-norm steps (the Jacobian is singular where a
// direction leaves R unchanged, e.g. the static position of a damper whose contacts all slip
// somewhere in the cycle). Starts from `initial` when given, then (if that fails) from the two
// linear limits (contacts stuck, or normal springs only), the better one first; each start gets
// options.max_iterations, `iterations` reports the total.
// Never throws on non-convergence: converged == false with a message; never returns NaN.
// `chord`: a factorized Jacobian carried from solve to solve (a sweep's), tried before each new
// factorization (linalg/damped_newton.hpp); null: Newton steps only.
[[nodiscard]] HbmSolution solve_at_frequency(const HarmonicBalance& system, double omega_rad_s,
                                             const std::optional<Eigen::VectorXd>& initial = std::nullopt,
                                             ChordFactorization* chord = nullptr);

// The same Newton iteration from `start` alone (no linear-limit starts): a continuation step,
// where another start would find another branch or waste the iterations.
[[nodiscard]] HbmSolution solve_from(const HarmonicBalance& system, double omega_rad_s, const Eigen::VectorXd& start,
                                     ChordFactorization* chord = nullptr);

}  // namespace bb::hbm
