// Bounds on what one analysis may ask of the machine, checked before it starts. An input whose
// estimated work or memory exceeds them is refused as bad input (exit 2) with the estimate, the
// bound and the key that sets the size, in well under a second, instead of running for hours or
// dying of std::bad_alloc. The bounds are stated and can be raised (`--max-work`, `--max-memory`).
#pragma once
#include <string>

#include "common/source_location.hpp"

namespace bb {

struct WorkLimits {
  // Estimated floating-point operations of the analysis's arithmetic (what it needs when every
  // solve converges: rough counts, upper bounds where H or the samples adapt). 1e12 is minutes of
  // arithmetic on one core, 2-3 times the costliest shipped case's estimate (4.5e11).
  double operations = 1e12;
  double bytes = 0.0;  // 0: three quarters of this machine's physical memory
  double memory_bytes() const;
};

struct WorkEstimate {
  double operations = 0.0;
  double bytes = 0.0;
  std::string basis;  // how it was counted, e.g. "2500001 frequencies x 1 level x 15 unknowns"
  SourceLocation at;  // where the sizing key is
  std::string key;    // the key (or keys) to change, e.g. "analysis.step_hz"
};

// Throws InputError naming the key, the estimate and the bound when either is exceeded.
void require_within(const WorkEstimate& estimate, const WorkLimits& limits);

}  // namespace bb
