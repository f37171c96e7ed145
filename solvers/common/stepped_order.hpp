// Whether frequencies follow one stepped sine as a rig steps it: strictly up, or strictly down
// (the first two values say which), never repeating one. Shared by the readers of measured curves
// (CSV, Universal File) and the case's own [[analysis.stepped_sine]] frequencies, each of which
// words the message in its own location format.
#pragma once
#include <cstddef>
#include <optional>
#include <span>

namespace bb {

struct SteppedBreak {
  std::size_t index = 0;  // the first value that breaks the order (>= 1)
  bool down = false;      // the sweep's direction, from its first two values
};

// The first value out of order; nullopt when the values are one stepped sine (or fewer than two).
inline std::optional<SteppedBreak> first_unstepped(std::span<const double> f) {
  const bool down = f.size() > 1 && f[1] < f[0];
  for (std::size_t i = 1; i < f.size(); ++i)
    if (down ? !(f[i] < f[i - 1]) : !(f[i] > f[i - 1])) return SteppedBreak{i, down};
  return std::nullopt;
}

}  // namespace bb
