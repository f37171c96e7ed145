// Closed-form Timoshenko cantilever answers used as continuum references.
#pragma once

namespace bb {

struct RectangularBeam {
  double length = 0.0;          // L [m]
  double height = 0.0;          // h [m]
  double thickness = 0.0;       // t [m]
  double youngs_modulus = 0.0;  // E [Pa]
  double poisson_ratio = 0.0;   // nu, gives G = E / (2 (1 + nu))
  double shear_coefficient = 5.0 / 6.0;
};

// Tip deflection under a tip shear force P: P L^3 / (3 E I) + P L / (k G A).
double timoshenko_tip_deflection(const RectangularBeam& beam, double tip_force);

// The bending part alone (Euler-Bernoulli), to show how much shear contributes.
double euler_bernoulli_tip_deflection(const RectangularBeam& beam, double tip_force);

}  // namespace bb
