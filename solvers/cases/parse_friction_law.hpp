// The `law` key of a point contact ([[analysis.contact]] and [analysis.damper] of an hbm or time
// analysis, [analysis.contact] of a contact_loop): the friction law the solvers call
// (friction/friction_law.hpp) and, for a law of the Masing family, the SliderDistribution
// (friction/masing.hpp) that spreads it over Jenkins sliders, with that law's own keys. A new law
// is one branch here.
#pragma once
#include <memory>

#include "common/toml_reader.hpp"
#include "friction/friction_law.hpp"
#include "friction/masing.hpp"

namespace bb {

struct ContactLaw {
  std::shared_ptr<const friction::FrictionLaw> law = friction::jenkins_law();
  std::shared_ptr<const friction::SliderDistribution> distribution;  // null: the law itself, one slider
};

// Reads `law` ("jenkins", the default) and the chosen law's keys from r; checks them against the
// point `point` (kn, kt, mu, n0 already read from r); `two_directions` admits the laws of two
// tangential directions (coupled_slip). Fails (exit 2) naming the key.
ContactLaw parse_contact_law(TomlReader& r, const friction::PointParameters& point, bool two_directions);

// The same for a contact of one tangential direction whose law the solver sees as its sliders.
std::shared_ptr<const friction::SliderDistribution> parse_slider_distribution(TomlReader& r,
                                                                              const friction::PointParameters& point);

}  // namespace bb
