#include "hbm/harmonic_truncation.hpp"

#include <algorithm>

namespace bb::hbm {

double HarmonicTruncation::largest() const {
  return share.empty() ? 0.0 : *std::max_element(share.begin(), share.end());
}

int HarmonicTruncation::needed(double tolerance) const {
  for (int k = static_cast<int>(share.size()) - 1; k >= 0; --k)
    if (share[static_cast<size_t>(k)] > tolerance) return harmonics + 1 + k;
  return harmonics;
}

HarmonicTruncation harmonic_truncation(const HarmonicBalance& system, const Eigen::VectorXd& x, double omega) {
  using Eigen::Index;
  HarmonicTruncation t;
  t.harmonics = system.options().harmonics;
  const int samples = system.aft_options().samples;
  t.probe_harmonics = std::min(3 * t.harmonics, (samples - 1) / 2);
  if (t.probe_harmonics <= t.harmonics) {
    t.probe_harmonics = t.harmonics;
    t.ok = true;
    return t;
  }
  HbmOptions options = system.options();
  options.harmonics = t.probe_harmonics;
  options.aft.samples = samples;
  const HarmonicBalance probe(system.model(), options);
  const Index nc = static_cast<Index>(system.contact_dofs().size());
  const Index low = x.size(), all = probe.unknowns(), high = all - low;
  Eigen::VectorXd padded = Eigen::VectorXd::Zero(all);
  padded.head(low) = x;  // layout [c0, a1, b1, ...] per contact DOF: the higher harmonics follow
  const auto linear = probe.condense(omega);
  if (!linear) return t;
  const HarmonicBalance::Residual r = probe.residual(*linear, padded);
  if (!r.ok) return t;
  const Eigen::MatrixXd j_hh =
      (linear->operator_ + r.forces.jacobian).bottomRightCorner(high, high);
  // Minimum norm: a harmonic block may be singular (a damper held only by sliding contacts).
  const Eigen::VectorXd added = -j_hh.completeOrthogonalDecomposition().solve(r.residual.tail(high));
  if (!added.allFinite()) return t;
  const double motion = x.tail(low - nc).norm();
  for (int h = t.harmonics + 1; h <= t.probe_harmonics; ++h) {
    const Index at = (2 * static_cast<Index>(h - t.harmonics) - 2) * nc;  // a_h of the first contact DOF, in `added`
    const double size = added.segment(at, 2 * nc).norm();
    t.share.push_back(motion > 0.0 ? size / motion : (size > 0.0 ? 1.0 : 0.0));
  }
  t.ok = true;
  return t;
}

}  // namespace bb::hbm
