#include "friction/iwan_law.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace bb::friction {

void validate(const IwanParameters& p) {
  if (!(p.chi > -1.0 && p.chi <= 0.0))
    throw std::invalid_argument(
        fmt::format("Iwan element: the power-law exponent chi must lie in (-1, 0] (got {})", p.chi));
  if (!(std::isfinite(p.beta) && p.beta >= 0.0))
    throw std::invalid_argument(fmt::format("Iwan element: beta must be finite and >= 0 (got {})", p.beta));
  const int least = p.beta > 0.0 ? 2 : 1;
  if (p.sliders < least || p.sliders > 10000)
    throw std::invalid_argument(
        fmt::format("Iwan element: sliders must lie in [{}, 10000] (got {}; beta > 0 takes one for the macro-slip)",
                    least, p.sliders));
}

IwanDensity iwan_density(const IwanParameters& p, double kt, double slip_force) {
  validate(p);
  if (!(kt > 0.0) || !(slip_force > 0.0) || !std::isfinite(kt) || !std::isfinite(slip_force))
    throw std::invalid_argument(fmt::format(
        "Iwan element: the stiffness and the slip force must be finite and > 0 (got {}, {})", kt, slip_force));
  const double q = (p.chi + 1.0) / (p.chi + 2.0);
  IwanDensity d;
  d.chi = p.chi;
  d.phi_max = slip_force * (1.0 + p.beta) / (kt * (p.beta + q));
  d.r = slip_force * (p.chi + 1.0) / (std::pow(d.phi_max, p.chi + 2.0) * (p.beta + q));
  d.s = slip_force * p.beta / (d.phi_max * (p.beta + q));
  return d;
}

double iwan_cycle_energy(const IwanDensity& d, double amplitude) {
  const double c = d.chi;
  if (amplitude <= d.phi_max) return 4.0 * d.r * std::pow(amplitude, c + 3.0) / ((c + 2.0) * (c + 3.0));
  const double m = d.phi_max;
  return 4.0 * d.r * (amplitude * std::pow(m, c + 2.0) / (c + 2.0) - std::pow(m, c + 3.0) / (c + 3.0)) +
         4.0 * d.s * m * (amplitude - m);
}

namespace {

// Shares from the density of a unit point (kt = 1, slip force 1): stiffness and slip force of each
// interval over the totals, which are 1.
std::vector<SliderShare> iwan_shares(const IwanParameters& p) {
  const IwanDensity d = iwan_density(p, 1.0, 1.0);
  const int n = p.beta > 0.0 ? p.sliders - 1 : p.sliders;
  const double a = p.chi + 1.0, b = p.chi + 2.0;
  std::vector<SliderShare> shares;
  for (int j = 0; j < n; ++j) {
    const double lo = d.phi_max * std::pow(static_cast<double>(j) / n, 1.0 / a),
                 hi = d.phi_max * std::pow(static_cast<double>(j + 1) / n, 1.0 / a);
    shares.push_back({.stiffness = d.r * (std::pow(hi, a) - std::pow(lo, a)) / a,
                      .load = d.r * (std::pow(hi, b) - std::pow(lo, b)) / b});
  }
  if (p.beta > 0.0) shares.push_back({.stiffness = d.s, .load = d.s * d.phi_max});
  return shares;
}

}  // namespace

std::string iwan_share_problem(const IwanParameters& p) {
  validate(p);
  const std::vector<SliderShare> shares = iwan_shares(p);
  for (size_t j = 0; j < shares.size(); ++j)
    // Near chi = -1 the interval edges phi_max (j/n)^(1/(chi+1)) underflow: a slider of no stiffness.
    // A tiny slip force is a slider that slips at once; a subnormal or zero one is lost precision.
    if (!(shares[j].stiffness >= kMinIwanShare && std::isnormal(shares[j].load)))
      return fmt::format(
          "chi = {:.17g} with {} sliders gives slider {} a share of the stiffness of {:.3g} (at least {:g} needed) "
          "and of the slip force of {:.3g} (a normal double needed): too near -1 for double precision; raise chi "
          "or lower the sliders",
          p.chi, p.sliders, j + 1, shares[j].stiffness, kMinIwanShare, shares[j].load);
  return {};
}

IwanDistribution::IwanDistribution(const IwanParameters& p) : p_(p) {
  if (const std::string problem = iwan_share_problem(p); !problem.empty())
    throw std::invalid_argument("Iwan element: " + problem);
  shares_ = iwan_shares(p);
}

std::string IwanDistribution::describe() const {
  return fmt::format("Iwan (Segalman 2005): chi = {:g}, beta = {:g}, {} sliders", p_.chi, p_.beta, p_.sliders);
}

std::optional<double> IwanDistribution::closed_form_energy(const PointParameters& point, double amplitude) const {
  const double slip_force = point.mu * point.n0;
  if (!(slip_force > 0.0)) return std::nullopt;
  return iwan_cycle_energy(iwan_density(p_, point.kt, slip_force), amplitude);
}

double IwanDistribution::parameter(const std::string& name) const {
  if (name == "chi") return p_.chi;
  if (name == "beta") return p_.beta;
  return SliderDistribution::parameter(name);
}

std::shared_ptr<const SliderDistribution> IwanDistribution::with_parameter(const std::string& name,
                                                                           double value) const {
  IwanParameters p = p_;
  if (name == "chi")
    p.chi = value;
  else if (name == "beta")
    p.beta = value;
  else
    return SliderDistribution::with_parameter(name, value);
  return std::make_shared<IwanDistribution>(p);  // validates
}

}  // namespace bb::friction
