// The `law` key of a point contact ([[analysis.contact]] of an hbm or time analysis,
// [analysis.contact] of a contact_loop): which SliderDistribution (contact/friction_law.hpp) spreads
// it over Jenkins sliders, and that law's own keys. A new law of the Masing family is one branch here.
#pragma once
#include <memory>

#include "common/toml_reader.hpp"
#include "contact/friction_law.hpp"

namespace bb {

// Reads `law` ("jenkins", the default: one slider, null) and the chosen law's keys from r; checks
// them against the point `point` (kn, kt, mu, n0 already read from r). Fails (exit 2) naming the key.
std::shared_ptr<const contact::SliderDistribution> parse_slider_distribution(TomlReader& r,
                                                                             const contact::JenkinsParameters& point);

}  // namespace bb
