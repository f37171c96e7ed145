// The four-parameter Iwan element (Segalman, "A four-parameter Iwan model for lap-type joints",
// J Appl Mech 72, 2005) for bolted joints: damping that grows with amplitude as a power law while
// the stiffness barely drops, then macro-slip. Units: SI.
//
// The continuous element is a density of Jenkins elements over their slip displacement phi, each of
// stiffness rho(phi) d phi:  rho(phi) = R phi^chi on (0, phi_max] + S delta(phi - phi_max), with
// chi in (-1, 0] and beta = S phi_max^-(chi+1) (chi+1) / R >= 0 the weight of the last slip. Its
// stuck stiffness is K_T = kt and its macro-slip force F_S = mu N (at N = N0: mu N0), which fix
//   q = (chi+1)/(chi+2),  phi_max = F_S (1+beta) / (K_T (beta+q)),
//   R = F_S (chi+1) / (phi_max^(chi+2) (beta+q)),  S = F_S beta / (phi_max (beta+q)).
// Energy dissipated per cycle under u = A cos(theta) (Segalman eq 12 and its macro-slip extension):
//   A <= phi_max:  D = 4 R A^(chi+3) / ((chi+2)(chi+3))              (micro-slip: slope chi + 3)
//   A >  phi_max:  D = 4 R (A phi_max^(chi+2)/(chi+2) - phi_max^(chi+3)/(chi+3)) + 4 S phi_max (A - phi_max).
//
// The sliders. The power-law part is cut into n intervals of equal stiffness (edges
// phi_max (j/n)^(1/(chi+1)), dense where chi < 0 makes rho large), each one slider whose stiffness
// and slip force are the exact integrals of rho and rho phi over it; S is one slider more. So K_T and
// F_S hold exactly for any n, and the dissipation converges as the first slider's slip displacement
// phi_max n^(-1/(chi+1)) falls below the amplitude of interest.
#pragma once
#include "friction/masing.hpp"

namespace bb::friction {

struct IwanParameters {
  double chi = -0.5;  // power-law exponent, in (-1, 0]
  double beta = 0.0;  // weight of the macro-slip delta, >= 0
  int sliders = 32;   // sliders in all (the delta takes one when beta > 0), >= 1, >= 2 when beta > 0
};

// Throws std::invalid_argument naming the offending value.
void validate(const IwanParameters& p);
// The smallest share of the stiffness a slider may have: 1e-100, the input numbers' rule
// (common/input_number.hpp), below which a slider's kt underflows in the solvers.
inline constexpr double kMinIwanShare = 1e-100;
// Why the sliders of a valid `p` cannot be computed ("" when they can): chi so near -1 that a
// slider's share underflows (chi = -0.9999999999 with 32 sliders).
std::string iwan_share_problem(const IwanParameters& p);

// The continuous density for a point of stuck stiffness kt and macro-slip force slip_force (> 0 each).
struct IwanDensity {
  double r = 0.0, s = 0.0, phi_max = 0.0, chi = 0.0;
};
IwanDensity iwan_density(const IwanParameters& p, double kt, double slip_force);
// D above [J]; amplitude >= 0.
double iwan_cycle_energy(const IwanDensity& d, double amplitude);

class IwanDistribution final : public SliderDistribution {
 public:
  explicit IwanDistribution(const IwanParameters& p);  // validates, and refuses an iwan_share_problem
  std::string describe() const override;
  std::vector<SliderShare> shares() const override { return shares_; }
  // At N0 (slip force mu N0); empty when mu N0 = 0.
  std::optional<double> closed_form_energy(const PointParameters& point, double amplitude) const override;
  // chi and beta. Beta's slider exists only when beta > 0: at 0 the power law takes it back, so
  // the sliders (not the continuous law) jump there.
  std::vector<std::string> parameter_names() const override { return {"chi", "beta"}; }
  double parameter(const std::string& name) const override;
  std::shared_ptr<const SliderDistribution> with_parameter(const std::string& name, double value) const override;

 private:
  IwanParameters p_;
  std::vector<SliderShare> shares_;
};

}  // namespace bb::friction
