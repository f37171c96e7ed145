// The friction law's one interface: what every solver asks of the law of a point contact, one call
// per contact per AFT evaluation or per time step (never per sample: the law marches its own
// samples). The harmonic balance (hbm/), its sensitivities, the Newmark step (timeint/) and the
// exact flow of shooting reach the law only through this header; a new law is a class behind it,
// its test and its parser entry (cases/parse_friction_law.cpp).
//
// Every law here shares the point's parameters (friction/jenkins.hpp's PointParameters: the normal
// spring kn and preload N0, N = max(N0 + kn v, 0), the stuck tangential stiffness kt and the
// Coulomb limit mu N); the stuck limit (friction_system.hpp's stuck_stiffness) and calibration read
// those. A law may act along one tangential direction (Jenkins) or two (coupled slip,
// friction/coupled_slip.hpp). Units: SI.
#pragma once
#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

#include "friction/aft.hpp"
#include "friction/jenkins.hpp"

namespace bb::friction {

// One implicit step of a law from its slider state to the displacements at the end of the step,
// with the consistent tangent a Newton iteration needs. A law of one direction fills the first
// entries only.
struct LawStep {
  Eigen::Vector2d tangential = Eigen::Vector2d::Zero();  // T [N]
  double normal = 0.0;                                   // N [N], >= 0
  Eigen::Vector2d slider = Eigen::Vector2d::Zero();      // w after the step [m]
  ContactState state = ContactState::stick;              // a slip of a 2D law reports slip_positive
  Eigen::Matrix2d dt_du = Eigen::Matrix2d::Zero();       // dT/du [N/m]
  Eigen::Vector2d dt_dv = Eigen::Vector2d::Zero();       // dT/dv [N/m]
  double dn_dv = 0.0;                                    // dN/dv [N/m]; dN/du is zero
};

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;
  // Its `law` key in a case ("jenkins", "coupled_slip").
  virtual std::string name() const = 0;
  // One line for the reports: the law and how the solvers treat it.
  virtual std::string describe() const = 0;
  // Tangential directions d it acts along: 1 or 2.
  virtual int directions() const = 0;
  // The frequency domain (AFT), in friction/aft.hpp's layout: u holds the d directions' coefficient
  // vectors one after the other (d (2H + 1)), v the normal one's; the result stacks T likewise
  // (tangential d m, dtangential_du d m x d m, dtangential_dv d m x m, dnormal_dv m x m; m = 2H + 1),
  // and its sampled u, t, w are the first direction's. Sampled or event-resolved as
  // options.resolve_events asks where the law has both; the law derivatives (options.law_derivatives,
  // columns LawParameter) where it has them. Throws std::invalid_argument naming what it lacks.
  virtual AftResult harmonics(const PointParameters& point, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                              const AftOptions& options) const = 0;
  // The time domain: one implicit step from `slider` (w before the step) to (u, v).
  virtual LawStep step(const PointParameters& point, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
                       double v) const = 0;
  // Whether the exact flow of shooting (timeint/piecewise_flow.hpp) integrates it: stick, slip at
  // +-mu N and lift-off as linear pieces in the point's parameters.
  virtual bool piecewise_linear() const = 0;
  // Whether the exact flow holds a stuck contact rigidly (Coulomb's stick, no tangential spring).
  virtual bool rigid_stick() const { return false; }
  // The law's own parameters beyond the point's kn, kt, mu, N0, by their case keys (a clearance
  // spring's "gap" and "k_gap"): what a calibration may vary. Empty for a law with none.
  virtual std::vector<std::string> parameter_names() const { return {}; }
  // One of them; std::invalid_argument naming the law's parameters when `name` is not one.
  virtual double parameter(const std::string& name) const;
  // The same law with `name` set to `value`; std::invalid_argument when the value leaves its domain.
  virtual std::shared_ptr<const FrictionLaw> with_parameter(const std::string& name, double value) const;
  // The law of the second and later sliders of a point whose Masing part is spread over sliders
  // (friction/masing.hpp); null when every slider has this law. A clearance spring acts once per
  // point, on the first slider (friction/clearance_spring.hpp).
  virtual std::shared_ptr<const FrictionLaw> later_sliders_law() const { return nullptr; }
};

// A law's own parameter asked that it does not have: throws std::invalid_argument "the <law> has no
// parameter '<name>'" with the law's own parameters. For FrictionLaw and SliderDistribution alike.
[[noreturn]] void throw_no_parameter(const std::string& law, const std::string& name,
                                     const std::vector<std::string>& own);

// The law of slider `slider` (from 0) of a point whose law is `law`.
inline std::shared_ptr<const FrictionLaw> slider_law(const std::shared_ptr<const FrictionLaw>& law, size_t slider) {
  if (slider == 0) return law;
  std::shared_ptr<const FrictionLaw> later = law->later_sliders_law();
  return later ? later : law;
}

// The Jenkins (elastic-Coulomb) slider of friction/jenkins.hpp: one direction, piecewise linear,
// sampled or event-resolved AFT, law derivatives. One shared instance.
const std::shared_ptr<const FrictionLaw>& jenkins_law();

}  // namespace bb::friction
