#include "study/timoshenko.hpp"

namespace bb {

double euler_bernoulli_tip_deflection(const RectangularBeam& b, double tip_force) {
  const double inertia = b.thickness * b.height * b.height * b.height / 12.0;
  return tip_force * b.length * b.length * b.length / (3.0 * b.youngs_modulus * inertia);
}

double timoshenko_tip_deflection(const RectangularBeam& b, double tip_force) {
  const double shear_modulus = b.youngs_modulus / (2.0 * (1.0 + b.poisson_ratio));
  const double area = b.thickness * b.height;
  return euler_bernoulli_tip_deflection(b, tip_force) +
         tip_force * b.length / (b.shear_coefficient * shear_modulus * area);
}

}  // namespace bb
