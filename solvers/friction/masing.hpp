// The Masing family of friction laws. A point contact of variable normal load whose tangential
// force is carried by Jenkins sliders acting in parallel on the same relative motion (the Masing
// family: the Jenkins element is one slider, the Iwan element a distribution of them). The
// harmonic balance (its AFT), Newmark, the exact flow that shooting integrates, the nonlinear modes
// and the sensitivities all see a law as its sliders, each an ordinary Jenkins contact
// (friction/jenkins.hpp): a new law of this family is one SliderDistribution, its test and
// its parser entry. A law outside it (a smooth Dahl or Bouc-Wen law, the coupled 2D slip of
// friction/coupled_slip.hpp) is a class behind friction/friction_law.hpp instead.
//
// The split. Slider i takes a share c_i of the point's stuck tangential stiffness kt and a share
// s_i of its normal law (kn_i = s_i kn, N0_i = s_i N0), with the point's mu: the sliders' normal
// loads add up to N = max(N0 + kn v, 0) and open together, slider i slips at |T_i| = mu s_i N,
// its slip displacement is mu s_i N / (c_i kt), and when all slip the point carries mu N. Units: SI.
#pragma once
#include <Eigen/Dense>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "friction/aft.hpp"
#include "friction/jenkins.hpp"

namespace bb::friction {

// One slider's shares of the point's stuck stiffness and of its normal law (so of its slip force).
struct SliderShare {
  double stiffness = 0.0;  // c_i
  double load = 0.0;       // s_i
};

// How a law spreads a point contact over its sliders, listed from the first to slip (the smallest
// slip displacement s_i / c_i) to the last. Each kind of share adds up to 1.
class SliderDistribution {
 public:
  virtual ~SliderDistribution() = default;
  virtual std::string describe() const = 0;  // its name and parameters, one line for the reports
  virtual std::vector<SliderShare> shares() const = 0;
  // Energy dissipated per cycle by the continuous law (not its sliders) under u = A cos(theta) at
  // the constant normal load `point.n0` [J]; empty when the law has no closed form.
  virtual std::optional<double> closed_form_energy(const PointParameters& point, double amplitude) const = 0;
  // The law's own parameters (beyond the point's kn, kt, mu, N0) by their case keys, e.g. Iwan's
  // "chi" and "beta": what a calibration may vary. Empty for a law with none.
  virtual std::vector<std::string> parameter_names() const { return {}; }
  // One of them; std::invalid_argument naming the law's parameters when `name` is not one.
  virtual double parameter(const std::string& name) const;
  // The same law with `name` set to `value`; std::invalid_argument when the value leaves its domain.
  virtual std::shared_ptr<const SliderDistribution> with_parameter(const std::string& name, double value) const;
};

// The point's sliders (one, the point itself, when `distribution` is null).
std::vector<PointParameters> parallel_sliders(const PointParameters& point, const SliderDistribution* distribution);

// The AFT of the whole point: the sum of its sliders' (friction/aft.hpp, with the same options): the
// forces, their derivatives (the law's with respect to the point's kn, kt, mu, N0) and the sampled
// t, n are the point's; `state` and `w` are those of the first slider to slip (whether the point
// slips at all), `closed` holds when every slider's loop closed. Throws as aft_jenkins.
[[nodiscard]] AftResult aft_parallel(const PointParameters& point, const SliderDistribution* distribution,
                                     const Eigen::VectorXd& u, const Eigen::VectorXd& v, const AftOptions& options);

}  // namespace bb::friction
