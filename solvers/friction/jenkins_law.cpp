// The Jenkins slider behind the friction-law interface: friction/jenkins.hpp's step, and its AFT
// sampled (friction/aft.hpp) or event-resolved (friction/aft_events.hpp): the choice is the law's.
#include "friction/aft_events.hpp"
#include "friction/friction_law.hpp"

namespace bb::friction {

AftResult aft_jenkins(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                      const AftOptions& options) {
  checked_aft_inputs(p, u, v, options);
  return options.resolve_events ? aft_jenkins_events(p, u, v, options) : aft_jenkins_sampled(p, u, v, options);
}

namespace {

class JenkinsLaw final : public FrictionLaw {
 public:
  std::string name() const override { return "jenkins"; }
  std::string describe() const override { return "Jenkins slider (stuck on kt, slip at mu N)"; }
  int directions() const override { return 1; }
  AftResult harmonics(const PointParameters& point, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                      const AftOptions& options) const override {
    return aft_jenkins(point, u, v, options);
  }
  // Stick dT/du = kt; slip dT/dv = +-mu kn; N > 0: dN/dv = kn; lift-off all zero.
  LawStep step(const PointParameters& point, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
               double v) const override {
    const JenkinsStep s = jenkins_step(point, slider[0], u[0], v);
    LawStep out;
    out.tangential[0] = s.tangential;
    out.normal = s.normal;
    out.slider[0] = s.slider;
    out.state = s.state;
    switch (s.state) {
      case ContactState::stick:
        out.dt_du(0, 0) = point.kt;
        out.dn_dv = point.kn;
        break;
      case ContactState::slip_positive:
      case ContactState::slip_negative:
        out.dt_dv[0] = (s.state == ContactState::slip_positive ? 1.0 : -1.0) * point.mu * point.kn;
        out.dn_dv = point.kn;
        break;
      case ContactState::lift_off:
        break;
    }
    return out;
  }
  bool piecewise_linear() const override { return true; }
};

}  // namespace

const std::shared_ptr<const FrictionLaw>& jenkins_law() {
  static const std::shared_ptr<const FrictionLaw> law = std::make_shared<JenkinsLaw>();
  return law;
}

}  // namespace bb::friction
