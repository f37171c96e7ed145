// What a harmonic-balance solution with H harmonics leaves out: the harmonics above H that its
// own contact forces excite. Units: SI.
//
// The solution x (H harmonics) is embedded in a balance of P > H harmonics, its higher
// coefficients zero. Its residual there is the contact forces' content at harmonics H+1..P (the
// excitation has none). One Newton step on those harmonics, the lower ones held, J_hh d_h = -R_h
// with J = L + dg/dx of the larger balance (exact AFT Jacobian, so a stuck contact's stiffness
// counts; directions restrained by less than 1e-6 of the block's stiffest, mechanisms, left out),
// gives the motion they would add at the contact DOFs; the recovery of the other DOFs (no
// load above the first harmonic) carries it to every DOF. A harmonic's share at a response DOF is
// the amplitude it would add there relative to the amplitude of the solution's harmonics 1..H
// there; the share of the harmonic is the largest over the response DOFs (per DOF, so that units
// do not mix, a damper's rotation against blade displacements, and the DOFs a user reads decide).
// This is the response-based criterion of adaptive harmonic balance (Jaumouille, Sinou &
// Petitjean, J. Sound Vib. 329 (2010) 4048-4067). It measures the waveform the truncation leaves
// out, not how much the harmonics kept would move if more were admitted.
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <vector>

#include "hbm/condensed_balance.hpp"

namespace bb::hbm {

struct HarmonicTruncation {
  int harmonics = 0;          // H of the solution
  int probe_harmonics = 0;    // P: the shares cover harmonics H+1..P
  std::vector<double> share;  // share[k] of harmonic H + 1 + k (largest over the response DOFs)
  bool ok = false;            // false when the larger balance could not be evaluated at x

  // The largest share (0 when nothing above H could be resolved).
  double largest() const;
  // The highest harmonic whose share exceeds `tolerance`, or H when none does.
  int needed(double tolerance) const;
};

// The larger balance of P harmonics for the solutions of `system` (H harmonics), built once and
// evaluated at any number of them. P is 3 H, or less when the system's AFT samples resolve fewer
// harmonics ((samples - 1) / 2): the probe uses the same samples, so that it measures the
// harmonics and not the sampling.
class TruncationProbe {
 public:
  explicit TruncationProbe(const HarmonicBalance& system);

  // The shares of harmonics H+1..P for the solution x at omega, at the model DOFs `responses`
  // (empty: the contact DOFs), each relative to the amplitude of the solution's harmonics 1..H at
  // that DOF, or to scales[i] when given (e.g. the largest amplitude of a sweep, so that a point
  // far from resonance, whose own motion is small, is judged on the curve's scale). ok = false
  // when the larger balance cannot be evaluated at x (a loop that does not close, a singular D_oo).
  [[nodiscard]] HarmonicTruncation at(const Eigen::VectorXd& x, double omega,
                                      const std::vector<Eigen::Index>& responses = {},
                                      const std::vector<double>& scales = {}) const;

 private:
  const HarmonicBalance& system_;
  int harmonics_ = 0, probe_harmonics_ = 0;
  std::optional<HarmonicBalance> probe_;  // none when P = H
};

// One evaluation: TruncationProbe(system).at(x, omega, responses, scales).
[[nodiscard]] HarmonicTruncation harmonic_truncation(const HarmonicBalance& system, const Eigen::VectorXd& x,
                                                     double omega, const std::vector<Eigen::Index>& responses = {},
                                                     const std::vector<double>& scales = {});

}  // namespace bb::hbm
