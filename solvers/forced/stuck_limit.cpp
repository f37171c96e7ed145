#include "forced/stuck_limit.hpp"

#include <complex>

namespace bb {

Eigen::VectorXcd stuck_response(const friction::FrictionModel& m, double omega) {
  // Harmonic 1 of a travelling wave: a cyclic contact couples its next sector with a phase.
  const Eigen::MatrixXcd stuck = friction::stuck_stiffness(m, 1);
  if (!m.nodal_diameters.empty()) {  // a cyclic sector: harmonic 1's nodal diameter
    const friction::NodalDiameterOperators& k1 = m.nodal_diameters.of_harmonic(1);
    const Eigen::MatrixXcd d = stuck + std::complex<double>(0.0, omega) * k1.damping - omega * omega * k1.mass;
    return d.partialPivLu().solve(m.harmonic_load);
  }
  const Eigen::MatrixXcd d = stuck + std::complex<double>(0.0, omega) * m.damping - omega * omega * m.mass;
  return d.partialPivLu().solve(m.harmonic_load);
}

}  // namespace bb
