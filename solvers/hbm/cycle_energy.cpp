#include "hbm/cycle_energy.hpp"

#include <complex>
#include <numbers>

#include "friction/aft.hpp"
#include "hbm/cyclic_shift.hpp"

namespace bb::hbm {

CycleEnergy cycle_energy(const HarmonicBalance& s, const HbmSolution& solution) {
  using Eigen::Index;
  const Eigen::MatrixXd q = s.recover(solution.x, solution.omega);
  const friction::FrictionModel& model = s.model();
  const Index n = q.rows();
  const int harmonics = s.options().harmonics;
  CycleEnergy e;
  // Excitation: f = Re F_h cos(h w t) - Im F_h sin(h w t) at each harmonic it has.
  for (Index i = 0; i < n; ++i) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(q.cols()), qi = q.row(i).transpose();
    for (int h = 1; h <= harmonics; ++h) {
      const std::complex<double> load = friction::excitation_at(model, h)[i];
      f[2 * h - 1] = load.real();
      f[2 * h] = -load.imag();
    }
    e.excitation += friction::cycle_work(f, qi);
  }
  // Viscous: integral over a period of q'^T C q' = pi h^2 w (a^T C a + b^T C b) per harmonic.
  // With a cyclic sector's Hermitian C_k: pi h^2 w Z^H C_k Z, Z = a - i b (real for Hermitian C_k).
  if (!model.nodal_diameters.empty())
    for (int h = 1; h <= harmonics; ++h) {
      const Eigen::VectorXcd z = q.col(2 * h - 1).cast<std::complex<double>>() -
                                 std::complex<double>(0.0, 1.0) * q.col(2 * h).cast<std::complex<double>>();
      e.viscous +=
          std::numbers::pi * h * h * solution.omega * z.dot(model.nodal_diameters.of_harmonic(h).damping * z).real();
    }
  else if (model.damping.size() > 0)
    for (int h = 1; h <= harmonics; ++h) {
      const Eigen::VectorXd a = q.col(2 * h - 1), b = q.col(2 * h);
      e.viscous += std::numbers::pi * h * h * solution.omega * (a.dot(model.damping * a) + b.dot(model.damping * b));
    }
  for (size_t k = 0; k < solution.contacts.size() && k < model.contacts.size(); ++k) {
    const friction::AftResult& r = solution.contacts[k];
    const friction::ContactElement& c = model.contacts[k];
    Eigen::VectorXd u = (c.tangential * q).transpose(), v = (c.normal * q).transpose();
    if (c.cyclic()) {
      u += shift_coefficients((c.tangential_next * q).transpose(), c.next_phase);
      v += shift_coefficients((c.normal_next * q).transpose(), c.next_phase);
    }
    const Eigen::Index m = u.size();
    e.friction += friction::cycle_work(r.tangential.head(m), u);
    if (c.tangential_2.size() > 0)
      e.friction += friction::cycle_work(r.tangential.tail(m), Eigen::VectorXd((c.tangential_2 * q).transpose()));
    e.normal += friction::cycle_work(r.normal, v);
  }
  return e;
}

}  // namespace bb::hbm
