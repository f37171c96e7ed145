#include "cases/parse_friction_law.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "contact/iwan_law.hpp"

namespace bb {

std::shared_ptr<const contact::SliderDistribution> parse_slider_distribution(TomlReader& r,
                                                                             const contact::JenkinsParameters& point) {
  const std::string law = r.choice("law", {"jenkins", "iwan"}, "jenkins");
  if (law == "jenkins") return nullptr;
  contact::IwanParameters p;
  p.chi = r.number("chi");
  if (!(p.chi > -1.0 && p.chi <= 0.0))
    r.fail("chi", fmt::format("the Iwan power-law exponent must lie in (-1, 0], found {}", p.chi));
  p.beta = r.non_negative("beta", 0.0);
  if (const auto n = r.optional_integer("sliders", 1, 10000)) p.sliders = static_cast<int>(*n);
  if (!(point.mu * point.n0 > 0.0))
    r.fail("mu", fmt::format("an Iwan element needs a positive slip force mu n0 (the macro-slip force at the preload), "
                             "found mu = {}, n0 = {}",
                             point.mu, point.n0));
  std::string problem;
  try {
    problem = contact::iwan_share_problem(p);
  } catch (const std::invalid_argument& e) {
    r.fail("sliders", e.what());
  }
  if (!problem.empty()) r.fail("chi", problem);
  return std::make_shared<contact::IwanDistribution>(p);
}

}  // namespace bb
