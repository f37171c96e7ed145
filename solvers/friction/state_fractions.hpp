// Share of a sampled period a contact spends in each state of Table X (stick, slip either way,
// lift-off): the contact-state maps of the harmonic-balance peaks and of the nonlinear modes.
#pragma once
#include <vector>

#include "friction/jenkins.hpp"

namespace bb::friction {

struct StateFractions {
  double stick = 0.0, slip = 0.0, lift_off = 0.0;
};

inline StateFractions state_fractions(const std::vector<ContactState>& states) {
  StateFractions f;
  if (states.empty()) return f;
  for (const ContactState s : states) {
    if (s == ContactState::stick)
      f.stick += 1;
    else if (s == ContactState::lift_off)
      f.lift_off += 1;
    else
      f.slip += 1;
  }
  const double n = static_cast<double>(states.size());
  f.stick /= n, f.slip /= n, f.lift_off /= n;
  return f;
}

}  // namespace bb::friction
