// What a linear forced-response (FRF) analysis computes: the sweep, the damping, the forces and
// responses, and the models compared (the full mesh by modal superposition, reduced models).
#pragma once
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/modal_spec.hpp"
#include "forced/linear_model_spec.hpp"
#include "model/model.hpp"
#include "reduction/reduced_model.hpp"

namespace bb {

// A nodal DOF named by a one-node set and a direction, written "T2.x".
struct FrfSpec {
  double f_min = 0.0, f_max = 0.0;  // [Hz]
  double step = 0.0;                // fixed grid step [Hz], the coarse step when adaptive
  bool adaptive = false;            // refine around peaks down to min_step
  double min_step = 0.0;
  FrfDamping damping;
  bool full_model = true;            // the full mesh, by modal superposition
  int full_modes = 20;               // modes of the full mesh kept in the superposition
  bool residual_flexibility = true;  // static correction for the truncated modes
  std::vector<FrfForce> forces;
  std::vector<PointDof> responses;
  std::vector<double> force_levels;  // linearity: amplitude of the first force at each level [N]
  std::vector<RomSpec> roms;
  double peak_prominence = 1.05;  // a peak stands this factor above its neighbouring minima
  // Peaks below this fraction of a model's largest response are round-off, e.g. of a response
  // that symmetry makes exactly zero.
  double peak_floor = 1e-8;
  double match_tolerance = 0.10;      // a peak names a mode within this relative distance
  std::optional<ModePairSpec> pairs;  // labels of the full mesh's modes (in-phase / out-of-phase, type)
};

}  // namespace bb
