#include "common/run_time_module.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <filesystem>

#include "common/errors.hpp"

namespace bb {

void* run_time_module_entry(const std::vector<std::string>& candidates, const char* entry, const std::string& what) {
  std::string tried;
  for (const std::string& path : candidates) {
    if (!std::filesystem::exists(path)) {
      tried += fmt::format("{}{} (missing)", tried.empty() ? "" : ", ", path);
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw SolverError(fmt::format("cannot load {} {}: {}", what, path, dlerror()));
    void* symbol = dlsym(handle, entry);
    if (!symbol) throw SolverError(fmt::format("{} is not {} (no {})", path, what, entry));
    return symbol;
  }
  throw SolverError(fmt::format("{} was not found (looked for {})", what, tried));
}

}  // namespace bb
