#include "common/work_limits.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include "common/errors.hpp"

namespace bb {

double WorkLimits::memory_bytes() const {
  if (bytes > 0.0) return bytes;
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  // Unknown: assume the smallest machine the project plans for (24 GiB).
  const double physical =
      pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 24.0 * (1 << 30);
  return 0.75 * physical;
}

void require_within(const WorkEstimate& e, const WorkLimits& limits) {
  const std::string where = e.at.file.empty() ? std::string() : e.at.where() + ": ";
  if (e.bytes > limits.memory_bytes())
    throw InputError(
        fmt::format("{}'{}': the analysis needs an estimated {:.3g} GB of memory ({}), above the bound of {:.3g} GB "
                    "(--max-memory, default three quarters of this machine's memory): reduce it",
                    where, e.key, e.bytes / 1e9, e.basis, limits.memory_bytes() / 1e9));
  if (e.operations > limits.operations)
    throw InputError(fmt::format(
        "{}'{}': the analysis needs an estimated {:.3g} floating-point operations ({}), above the bound of {:.3g} "
        "(--max-work raises it for those who mean it): reduce it",
        where, e.key, e.operations, e.basis, limits.operations));
}

}  // namespace bb
