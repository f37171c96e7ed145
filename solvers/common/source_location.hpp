// Where a value came from in a case file, for error messages.
#pragma once
#include <filesystem>
#include <string>

namespace bb {

struct SourceLocation {
  std::filesystem::path file;
  int line = 0;
  std::string where() const;  // "file:line"
};

}  // namespace bb
