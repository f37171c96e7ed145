#include "hbm/harmonic_truncation.hpp"

#include <algorithm>
#include <exception>

namespace bb::hbm {

double HarmonicTruncation::largest() const {
  return share.empty() ? 0.0 : *std::max_element(share.begin(), share.end());
}

int HarmonicTruncation::needed(double tolerance) const {
  for (int k = static_cast<int>(share.size()) - 1; k >= 0; --k)
    if (share[static_cast<size_t>(k)] > tolerance) return harmonics + 1 + k;
  return harmonics;
}

TruncationProbe::TruncationProbe(const HarmonicBalance& system)
    : system_(system),
      harmonics_(system.options().harmonics),
      probe_harmonics_(std::max(harmonics_, std::min(3 * harmonics_, (system.aft_options().samples - 1) / 2))) {
  if (probe_harmonics_ == harmonics_) return;
  HbmOptions options = system.options();
  options.harmonics = probe_harmonics_;
  options.aft = system.aft_options();
  probe_.emplace(system.model(), options);
}

HarmonicTruncation TruncationProbe::at(const Eigen::VectorXd& x, double omega,
                                       const std::vector<Eigen::Index>& responses,
                                       const std::vector<double>& scales) const {
  using Eigen::Index;
  HarmonicTruncation t;
  t.harmonics = harmonics_;
  t.probe_harmonics = probe_harmonics_;
  if (!probe_) {
    t.ok = true;
    return t;
  }
  const HarmonicBalance& probe = *probe_;
  Eigen::VectorXd padded = Eigen::VectorXd::Zero(probe.unknowns());
  padded.head(x.size()) = x;  // layout [c0, a1, b1, ...] per contact DOF: the higher harmonics follow
  const auto linear = probe.condense(omega);
  if (!linear) return t;
  const HarmonicBalance::Residual r = probe.residual(*linear, padded);
  if (!r.ok) return t;
  // One Newton step on the harmonics above H, the lower ones held. (A step on all of them would
  // also estimate how the kept harmonics move, but near a resonance the Jacobian is nearly
  // singular along the resonant motion and that part of the step is not a usable estimate:
  // measured on Table XI, changes of 40-390 % against 0.03-0.4 % between H = 1 and H = 7.)
  // Minimum norm, mechanisms left out: a direction restrained by less than kMechanism of the
  // block's stiffest (a damper held only by sliding contacts, turning against its own small
  // inertia) would take an unbounded step, while the contacts would stick again long before.
  // Table XI at 300 N: pivots of 3-13 against 6.2e8 made shares of 50-260 % where H = 7 moves the
  // peaks by 0.04 %.
  constexpr double kMechanism = 1e-6;
  const Index low = x.size(), high = probe.unknowns() - low;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> block;
  block.setThreshold(kMechanism);  // before compute: the rank shapes the decomposition
  block.compute((linear->operator_ + r.forces.jacobian).bottomRightCorner(high, high));
  const Eigen::VectorXd added = -block.solve(r.residual.tail(high));
  if (!added.allFinite()) return t;
  Eigen::VectorXd estimated = padded;
  estimated.tail(high) = added;
  Eigen::MatrixXd q;  // every model DOF's coefficients, [c0, a1, b1, ..., aP, bP]
  try {
    q = probe.recover(estimated, omega);
  } catch (const std::exception&) {
    return t;  // D_oo singular at some harmonic: no estimate
  }
  const std::vector<Index>& dofs = responses.empty() ? system_.contact_dofs() : responses;
  t.share.assign(static_cast<size_t>(t.probe_harmonics - t.harmonics), 0.0);
  for (size_t i = 0; i < dofs.size(); ++i) {
    const Index dof = dofs[i];
    const double motion = i < scales.size() ? scales[i] : q.row(dof).segment(1, 2 * t.harmonics).norm();
    for (int h = t.harmonics + 1; h <= t.probe_harmonics; ++h) {
      const double size = q.row(dof).segment(2 * h - 1, 2).norm();
      double& share = t.share[static_cast<size_t>(h - t.harmonics - 1)];
      share = std::max(share, motion > 0.0 ? size / motion : (size > 0.0 ? 1.0 : 0.0));
    }
  }
  t.ok = true;
  return t;
}

HarmonicTruncation harmonic_truncation(const HarmonicBalance& system, const Eigen::VectorXd& x, double omega,
                                       const std::vector<Eigen::Index>& responses, const std::vector<double>& scales) {
  return TruncationProbe(system).at(x, omega, responses, scales);
}

}  // namespace bb::hbm
