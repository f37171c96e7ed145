#include "friction/whole_ring.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace bb::friction {

using Index = Eigen::Index;

FrictionModel whole_ring(const FrictionModel& sector_model, int sectors) {
  if (sectors < 2) throw std::invalid_argument(fmt::format("whole ring: {} sectors; give at least 2", sectors));
  FrictionModel s = sector_model;
  validate_model(s, "whole ring", true);
  if (!s.nodal_diameters.empty())
    throw std::invalid_argument(
        "whole ring: the sector's linear part is cyclic itself (per nodal diameter): build the whole structure "
        "from its mesh instead");
  double phase = 0.0;
  for (const ContactElement& c : s.contacts)
    if (c.cyclic()) phase = c.next_phase;
  for (const ContactElement& c : s.contacts)
    if (c.cyclic() && c.next_phase != phase)
      throw std::invalid_argument("whole ring: the cyclic contacts have different inter-sector phases");
  const double order = phase * sectors / (2 * std::numbers::pi);
  if (std::abs(order - std::round(order)) > 1e-9)
    throw std::invalid_argument(
        fmt::format("whole ring: the phase {} rad is not 2 pi EO / {} for an integer EO", phase, sectors));
  const Index n = s.mass.rows(), w = n * sectors;
  FrictionModel whole{Eigen::MatrixXd::Zero(w, w), Eigen::MatrixXd::Zero(w, w), Eigen::MatrixXd::Zero(w, w), {},
                      Eigen::VectorXd::Zero(w),    Eigen::VectorXcd::Zero(w)};
  for (int j = 0; j < sectors; ++j) {
    const Index o = n * j, next = n * ((j + 1) % sectors);
    whole.mass.block(o, o, n, n) = s.mass;
    whole.damping.block(o, o, n, n) = s.damping;
    whole.stiffness.block(o, o, n, n) = s.stiffness;
    whole.static_load.segment(o, n) = s.static_load;
    whole.harmonic_load.segment(o, n) = s.harmonic_load * std::polar(1.0, j * phase);
    for (const ContactElement& c : s.contacts) {
      ContactElement e;
      e.point = c.point;
      e.tangential_offset = c.tangential_offset;
      e.tangential = Eigen::RowVectorXd::Zero(w);
      e.normal = Eigen::RowVectorXd::Zero(w);
      e.tangential.segment(o, n) = c.tangential;
      e.normal.segment(o, n) = c.normal;
      if (c.cyclic()) {
        e.tangential.segment(next, n) += c.tangential_next;
        e.normal.segment(next, n) += c.normal_next;
      }
      whole.contacts.push_back(std::move(e));
    }
  }
  return whole;
}

}  // namespace bb::friction
