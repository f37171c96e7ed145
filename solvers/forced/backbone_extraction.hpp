// A backbone point read directly from one response-controlled curve: the amplitude held, the
// natural frequency and damping ratio there, and the effective modal mass, by the force balance of
// one mode at a held amplitude a:
//   (F / a)^2 = m^2 ((w0^2 - w^2)^2 + 4 z^2 w0^2 w^2),
// which is exactly a parabola in w^2 whose vertex lies at w0^2 (1 - 2 z^2), with height
// 4 m^2 w0^4 z^2 (1 - z^2) and curvature m^2. The parabola is fitted by weighted linear least
// squares (relative weights: the measured force's noise is relative) in w^2 centred at the
// smallest measured force, so the vertex is not a difference of large numbers. The starting values
// of a nonlinear modal model's fit, and a check of it; the same in spirit as reading a backbone
// from phase-resonance tests, without a phase.
#pragma once
#include <vector>

namespace bb {

struct BackbonePoint {
  double amplitude_m = 0.0;    // the held displacement amplitude at the resonance
  double frequency_hz = 0.0;   // natural frequency f0
  double damping_ratio = 0.0;  // z
  double mass_kg = 0.0;        // effective modal mass at the point
  double rms_relative = 0.0;   // rms of the fit's relative force residuals
};

// From the points of one curve (frequency [Hz], displacement amplitude [m], force [N]); throws
// std::invalid_argument with fewer than 5 points, a non-positive value, or a curve with no
// resonance inside (the parabola's vertex outside the measured band, or not a minimum).
BackbonePoint extract_backbone_point(const std::vector<double>& frequency_hz, const std::vector<double>& amplitude_m,
                                     const std::vector<double>& force_n);

}  // namespace bb
