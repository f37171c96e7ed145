// What a harmonic-balance solution with H harmonics leaves out: the motion of the harmonics above H
// that its own contact forces excite. Units: SI.
//
// The solution x (H harmonics) is embedded in a balance of P > H harmonics with zero higher
// coefficients. Its residual there is the contact forces' content at harmonics H+1..P (the
// excitation has none); one Newton step on those harmonics alone, J_hh d_h = -R_h with J = L + dg/dx
// of the larger balance (contact stiffness included, so a stuck contact is not taken as free), gives
// the motion they would add. Each harmonic's share is the norm of its added coefficients over all
// contact DOFs, relative to the norm of the solution's harmonic part. This is the response-based
// criterion of adaptive harmonic balance (Jaumouille, Sinou & Petitjean, J. Sound Vib. 329 (2010)
// 4048-4067), evaluated with the exact AFT Jacobian.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "hbm/condensed_balance.hpp"

namespace bb::hbm {

struct HarmonicTruncation {
  int harmonics = 0;            // H of the solution
  int probe_harmonics = 0;      // P: the shares cover harmonics H+1..P
  std::vector<double> share;    // share[k] of harmonic H + 1 + k, relative to the solution's motion
  bool ok = false;              // false when the larger balance could not be evaluated at x

  // The largest share (0 when nothing above H could be resolved).
  double largest() const;
  // The highest harmonic whose share exceeds `tolerance`, or H when none does.
  int needed(double tolerance) const;
};

// The shares of harmonics H+1..P for the solution x at omega of `system` (H harmonics). P is
// 3 H, or less when the system's AFT samples resolve fewer harmonics ((samples - 1) / 2): the
// probe uses the same samples, so that it measures the harmonics and not the sampling.
[[nodiscard]] HarmonicTruncation harmonic_truncation(const HarmonicBalance& system, const Eigen::VectorXd& x,
                                                     double omega);

}  // namespace bb::hbm
