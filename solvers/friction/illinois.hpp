// Regula falsi with the Illinois modification: the root of a smooth function of the phase theta
// on a bracket, to rounding. The event-resolved AFT (friction/aft_events.cpp) and the clearance
// spring (friction/clearance_spring.cpp) locate the ends of their pieces with it.
#pragma once
#include <cmath>

#include "common/constants.hpp"

namespace bb::friction {

// On [lo, hi], f(lo) and f(hi) of opposite signs; superlinear for a smooth f.
template <typename F>
double illinois(F&& f, double lo, double hi, double f_lo, double f_hi) {
  const double resolution = 1e-15 * kTwoPi;
  int side = 0;
  for (int i = 0; i < 100 && hi - lo > resolution; ++i) {
    double mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
    const double fm = f(mid);
    if (std::abs(fm) <= 1e-15 * (std::abs(f_lo) + std::abs(f_hi))) return mid;
    if ((fm > 0.0) == (f_hi > 0.0)) {
      hi = mid;
      f_hi = fm;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    } else {
      lo = mid;
      f_lo = fm;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    }
  }
  return hi;
}

}  // namespace bb::friction
