#include "friction/friction_law.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

namespace bb::friction {

namespace {

[[noreturn]] void no_parameter(const FrictionLaw& law, const std::string& name) {
  const std::vector<std::string> names = law.parameter_names();
  throw std::invalid_argument(fmt::format(
      "the {} law has no parameter '{}' ({})", law.name(), name,
      names.empty() ? std::string("it has none of its own") : fmt::format("its own: {}", fmt::join(names, ", "))));
}

}  // namespace

double FrictionLaw::parameter(const std::string& name) const { no_parameter(*this, name); }

std::shared_ptr<const FrictionLaw> FrictionLaw::with_parameter(const std::string& name, double) const {
  no_parameter(*this, name);
}

}  // namespace bb::friction
