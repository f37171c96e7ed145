// A Masing law in parallel with a clearance spring: a law outside the Masing family whose damping
// and stiffness change decouple (issue 68). The friction part (a Jenkins slider, or the first of an
// Iwan joint's sliders) dissipates and softens as every Masing law does; the clearance spring
// f(u) = k_gap sign(u) max(|u| - gap, 0) is elastic and engages past the gap, so it stiffens with
// amplitude without dissipating. Together the resonance may stay put while the damping grows, which
// no single Masing law can do (its added damping is tied to its softening). It models the contact
// stiffening of a joint whose asperities or a stop engage with amplitude. Units: SI.
//
// The spring acts on the tangential relative displacement u whatever the normal load (an elastic
// element in parallel with the contact, not a part of it). With gap > 0 it is slack at rest, so the
// point's stuck stiffness (the stuck limit's kt) holds below the gap. Under u = A cos(theta) its
// first harmonic is the describing function of a dead zone,
//   K1(A) = k_gap (1 - (2/pi)(asin(r) + r sqrt(1 - r^2))),  r = gap / A  (A > gap; 0 below),
// and it adds no dissipation: the energy per cycle is the friction part's alone.
#pragma once
#include <memory>
#include <vector>

#include "friction/friction_law.hpp"

namespace bb::friction {

// One spring (springs = 1), or `springs` springs sharing k_gap equally with gaps log-spaced from
// gap to gap_max: a spread of engagement amplitudes (asperities of many heights) that stiffens
// smoothly over the decade between them, as a spread of slip displacements (an Iwan joint)
// softens and dissipates smoothly.
struct ClearanceSpring {
  double gap = 0.0;        // the first gap [m], > 0
  double stiffness = 0.0;  // k_gap, all the springs together [N/m], >= 0
  double gap_max = 0.0;    // the last gap [m], > gap when springs > 1 (0 for one spring)
  int springs = 1;         // in [1, 1000]
};

struct SpringShare {
  double gap = 0.0, stiffness = 0.0;
};

// Throws std::invalid_argument naming the offending value.
void validate(const ClearanceSpring& s);
// Each spring's gap and stiffness, by increasing gap.
std::vector<SpringShare> clearance_springs(const ClearanceSpring& s);
// f(u) [N] and its slope df/du [N/m], summed over the springs.
double clearance_force(const ClearanceSpring& s, double u);
double clearance_slope(const ClearanceSpring& s, double u);
// K1(A) above, summed over the springs [N/m]; amplitude >= 0.
double clearance_describing_stiffness(const ClearanceSpring& s, double amplitude);

// `masing` (a law of one direction: jenkins) in parallel with the spring. The spring's harmonics are
// integrated exactly over the pieces where it is engaged, their ends bracketed by the AFT's samples
// (options.samples): a piece shorter than a sample interval may be missed, as an event may be by
// the event-resolved AFT. Its own parameters, for calibration, are "gap", "k_gap" and, for a spread
// of springs, "gap_max". Throws
// std::invalid_argument for a law of two directions or a spring that fails validate().
std::shared_ptr<const FrictionLaw> with_clearance_spring(std::shared_ptr<const FrictionLaw> masing,
                                                         const ClearanceSpring& spring);

}  // namespace bb::friction
