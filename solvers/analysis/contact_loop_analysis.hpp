// The friction-contact test rig (analysis type "contact_loop"): the steady hysteresis loop of one
// Jenkins contact under an imposed relative motion (analysis/contact_loop_spec.hpp), sampled by the
// AFT march of friction/aft.hpp with H = 1 inputs, its dissipated energy, stick/slip/lift-off
// fractions and first-harmonic describing function, with the closed forms at constant normal load.
// Units: SI.
#pragma once
#include "analysis/contact_loop_spec.hpp"
#include "friction/aft.hpp"
#include "results/table.hpp"

namespace bb {

// Jenkins element at constant normal load n0 under u = U cos(theta), slip force Fs = mu n0, slip
// displacement xs = Fs / kt. For U > xs the loop is a parallelogram: energy 4 Fs (U - xs) per cycle;
// first harmonic of T = k_eq U cos(theta) - c_eq U sin(theta), the classic describing function of
// the Jenkins element (Griffin 1980, ASME J Eng Power 102; Menq, Griffin & Bielak 1986)
//   k_eq = kt / pi (beta - sin(2 beta) / 2),  cos(beta) = 1 - 2 xs / U,
//   c_eq = 4 Fs (U - xs) / (pi U^2)  (= energy / (pi U^2)).
// For U <= xs the contact sticks throughout: k_eq = kt, c_eq = 0, no energy.
struct JenkinsLoopClosedForm {
  double energy = 0.0;     // [J] per cycle
  double stiffness = 0.0;  // k_eq [N/m]
  double damping = 0.0;    // c_eq [N/m], the quadrature (loss) stiffness
};
// Throws std::invalid_argument for invalid parameters or U <= 0.
JenkinsLoopClosedForm jenkins_loop_closed_form(const friction::PointParameters& law, double amplitude);

// Fraction of the period with n0 + kn V cos(.) < 0: the arc cos(x) < -c, c = n0 / (kn V), has length
// 2 acos(c), so acos(c) / pi; 0 when kn V <= n0.
double lift_off_fraction_closed_form(const friction::PointParameters& law, double normal_amplitude);

struct ContactLoopSummary {
  double dissipated_energy = 0.0;     // loop area, trapezoid over the samples [J]
  double max_tangential_force = 0.0;  // max |T| [N]
  double stick_slope = 0.0;           // slope of T(u) within the stick segments [N/m]; NaN without one
  double stick_fraction = 0.0, slip_fraction = 0.0, lift_off_fraction = 0.0;  // of the samples
  double equivalent_stiffness = 0.0;                                          // a1 / U [N/m]
  double equivalent_damping = 0.0;                                            // -b1 / U [N/m]
  double max_t_over_mu_n = 0.0;               // over the closed samples: 1 where it slips
  double max_force_when_open = 0.0;           // max(|T|, N) over the lift-off samples [N]
  double min_normal = 0.0, max_normal = 0.0;  // [N]
};

struct ContactLoopOutcome {
  ResultTables tables;      // hysteresis, loop_summary
  friction::AftResult aft;  // the last marched period at the samples, and the periods/closure record
  ContactLoopSummary summary;
};

// Throws std::invalid_argument for a spec the parser would reject; a loop that does not close is
// reported (loop_summary closed = 0), never thrown.
ContactLoopOutcome run_contact_loop(const ContactLoopSpec& spec);

// The loop's numbers from a marched period (exposed for the unit tests).
ContactLoopSummary summarise_loop(const friction::PointParameters& law, double tangential_amplitude,
                                  const friction::AftResult& aft);

}  // namespace bb
