#include "friction/friction_law.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

namespace bb::friction {

void throw_no_parameter(const std::string& law, const std::string& name, const std::vector<std::string>& own) {
  throw std::invalid_argument(fmt::format(
      "the {} has no parameter '{}' ({})", law, name,
      own.empty() ? std::string("it has none of its own") : fmt::format("its own: {}", fmt::join(own, ", "))));
}

double FrictionLaw::parameter(const std::string& name) const {
  throw_no_parameter(this->name() + " law", name, parameter_names());
}

std::shared_ptr<const FrictionLaw> FrictionLaw::with_parameter(const std::string& name, double) const {
  throw_no_parameter(this->name() + " law", name, parameter_names());
}

}  // namespace bb::friction
