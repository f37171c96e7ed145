#include "cases/parse_friction_law.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "friction/clearance_spring.hpp"
#include "friction/coulomb_law.hpp"
#include "friction/coupled_slip.hpp"
#include "friction/iwan_law.hpp"

namespace bb {

namespace {

std::shared_ptr<const friction::SliderDistribution> parse_iwan(TomlReader& r, const friction::PointParameters& point) {
  friction::IwanParameters p;
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
    problem = friction::iwan_share_problem(p);
  } catch (const std::invalid_argument& e) {
    r.fail("sliders", e.what());
  }
  if (!problem.empty()) r.fail("chi", problem);
  return std::make_shared<friction::IwanDistribution>(p);
}

// A clearance spring beside a Masing law: both keys or neither.
std::shared_ptr<const friction::FrictionLaw> parse_clearance_spring(TomlReader& r,
                                                                    std::shared_ptr<const friction::FrictionLaw> law,
                                                                    const std::string& name) {
  const char* given = r.has("gap") ? "gap" : r.has("k_gap") ? "k_gap" : r.has("gap_max") ? "gap_max" : "gap_springs";
  if (name != "jenkins" && name != "iwan")
    r.fail(given,
           fmt::format("a clearance spring (gap, k_gap) sits beside a Masing law (jenkins or iwan), not {}", name));
  for (const char* key : {"gap", "k_gap"})
    if (!r.has(key))
      r.fail(given, fmt::format("a clearance spring needs both gap [m] and k_gap [N/m]; '{}' is missing", key));
  friction::ClearanceSpring spring;
  spring.gap = r.positive("gap");
  spring.stiffness = r.non_negative("k_gap", 0.0);
  if (r.has("gap_springs") && !r.has("gap_max"))
    r.fail("gap_springs", "spreads the springs' gaps from gap to gap_max: give gap_max too");
  if (r.has("gap_max")) {
    spring.gap_max = r.positive("gap_max");
    if (!(spring.gap_max > spring.gap))
      r.fail("gap_max", fmt::format("must lie above the gap ({:g} m), found {:g} m", spring.gap, spring.gap_max));
    spring.springs = static_cast<int>(r.optional_integer("gap_springs", 2, 1000).value_or(16));
  }
  return friction::with_clearance_spring(std::move(law), spring);
}

}  // namespace

ContactLaw parse_contact_law(TomlReader& r, const friction::PointParameters& point, bool two_directions) {
  const std::string law = two_directions ? r.choice("law", {"jenkins", "coulomb", "iwan", "coupled_slip"}, "jenkins")
                                         : r.choice("law", {"jenkins", "coulomb", "iwan"}, "jenkins");
  ContactLaw out;
  if (law == "iwan") out.distribution = parse_iwan(r, point);
  if (law == "coulomb") out.law = friction::coulomb_law();
  if (law == "coupled_slip") out.law = friction::coupled_slip_law();
  if (r.has("gap") || r.has("k_gap") || r.has("gap_max") || r.has("gap_springs"))
    out.law = parse_clearance_spring(r, out.law, law);
  return out;
}

std::shared_ptr<const friction::SliderDistribution> parse_slider_distribution(TomlReader& r,
                                                                              const friction::PointParameters& point) {
  return r.choice("law", {"jenkins", "iwan"}, "jenkins") == "iwan" ? parse_iwan(r, point) : nullptr;
}

}  // namespace bb
