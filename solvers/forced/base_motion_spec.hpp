// Base excitation: the supports move, and every DOF of `influence` with them as a rigid body, at a
// prescribed acceleration a_b(t) = level * sum_h rho_h cos(h w t + psi_h), rho_1 = 1 (a shaker
// holds its table's acceleration; its distortion adds harmonics). Solved relative to the base,
//   M z'' + C z' + K z + g(z) = -M r a_b(t),   z = q - r u_b,
// with r the influence vector (each DOF's motion per metre of base motion): the responses and the
// contacts see the motion relative to the base, as a vibrometer referenced to the table does, and
// a contact "to the ground" is a contact to the moving base. Exact for a lumped model whose ground
// springs and dampers act between each DOF and the base; for a reduced model r must be its rigid
// motion with the base (the interface DOFs' translation, the modal coordinates' zero).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/source_location.hpp"
#include "forced/linear_model_spec.hpp"

namespace bb {

struct BaseHarmonic {
  int order = 1;           // h
  double ratio = 1.0;      // rho_h: acceleration amplitude relative to harmonic 1's
  double phase_deg = 0.0;  // psi_h
};

struct BaseMotionSpec {
  std::vector<std::pair<PointDof, double>> influence;  // r, by DOF
  std::vector<BaseHarmonic> harmonics;                 // harmonic 1 first, then ascending orders
  std::string file;  // the measured period its harmonics were read from; empty when written in the case
  SourceLocation at;

  int highest_order() const { return harmonics.empty() ? 1 : harmonics.back().order; }
};

}  // namespace bb
