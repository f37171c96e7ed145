// An impossible dimension of a parametric article, by name, so that a case parser can point at
// the line that set it.
#pragma once
#include <string>
#include <utility>

#include "common/errors.hpp"

namespace bb {

// InputError whose name() is the offending member of the article's dimensions (e.g. "H_n").
class DimensionError : public InputError {
 public:
  DimensionError(std::string name, const std::string& message) : InputError(message), name_(std::move(name)) {}
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

// Throws DimensionError unless `value`, the size called `name`, is positive and finite.
void require_positive_size(const char* name, double value);

}  // namespace bb
