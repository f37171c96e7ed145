#include "timeint/contact_step.hpp"

namespace bb::timeint {

ContactSample contact_step(const friction::ContactElement& contact, double slider_before, const Eigen::VectorXd& q) {
  const double u = contact.tangential.dot(q) - contact.tangential_offset;
  const double v = contact.normal.dot(q);
  const contact::JenkinsStep s = contact::jenkins_step(contact.law, slider_before, u, v);
  return {.u = u, .v = v, .tangential = s.tangential, .normal = s.normal, .slider = s.slider, .state = s.state};
}

ContactTangent contact_tangent(const friction::ContactElement& contact, const ContactSample& sample) {
  const contact::JenkinsParameters& p = contact.law;
  switch (sample.state) {
    case contact::ContactState::stick:
      return {.dt_du = p.kt, .dt_dv = 0.0, .dn_dv = p.kn};
    case contact::ContactState::slip_positive:
      return {.dt_du = 0.0, .dt_dv = p.mu * p.kn, .dn_dv = p.kn};
    case contact::ContactState::slip_negative:
      return {.dt_du = 0.0, .dt_dv = -p.mu * p.kn, .dn_dv = p.kn};
    case contact::ContactState::lift_off:
      return {};
  }
  return {};
}

}  // namespace bb::timeint
