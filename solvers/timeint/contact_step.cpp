#include "timeint/contact_step.hpp"

namespace bb::timeint {

ContactSample contact_step(const friction::ContactElement& contact, double slider_before, const Eigen::VectorXd& q) {
  const double u = contact.tangential.dot(q) - contact.tangential_offset;
  const double v = contact.normal.dot(q);
  const friction::LawStep s = contact.law->step(contact.point, {slider_before, 0.0}, {u, 0.0}, v);
  return {.u = u,
          .v = v,
          .tangential = s.tangential[0],
          .normal = s.normal,
          .slider = s.slider[0],
          .state = s.state,
          .tangent = {.dt_du = s.dt_du(0, 0), .dt_dv = s.dt_dv[0], .dn_dv = s.dn_dv}};
}

}  // namespace bb::timeint
