// What a contact_loop analysis computes: the friction-contact test rig. One point contact of any
// friction law (friction/masing.hpp; a Jenkins element unless the case names another) driven by an imposed periodic
// relative motion
//   u(theta) = U cos(theta),  v(theta) = V cos(theta + phi)   (v > 0 presses),
// and its steady hysteresis loop T(u). Units: SI, phase in degrees.
#pragma once
#include <memory>

#include "common/source_location.hpp"
#include "friction/jenkins.hpp"
#include "friction/masing.hpp"

namespace bb {

struct ContactLoopSpec {
  friction::PointParameters point;                                   // kn, kt, mu, n0, validated by the parser
  std::shared_ptr<const friction::SliderDistribution> distribution;  // null: one Jenkins slider
  double tangential_amplitude = 0;                                   // U [m], > 0
  double normal_amplitude = 0;                                       // V [m], >= 0; 0 keeps N = n0
  double normal_phase_deg = 0;                                       // phi [deg]
  int samples = 256;                                                 // per period, >= 16
  SourceLocation at;
};

}  // namespace bb
