// Wall time since a steady-clock instant, in seconds: the timings of the cost tables and reports.
#pragma once
#include <chrono>

namespace bb {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace bb
