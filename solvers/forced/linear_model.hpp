// The linear model a forced-response case asks for, built from its mesh or its files: the DOF
// of a point, a reduced model (Craig-Bampton, file or matrices), its damping matrix.
#pragma once
#include <Eigen/Dense>

#include <string>

#include "assembly/free_system.hpp"
#include "cache/model_cache_settings.hpp"
#include "forced/linear_model_spec.hpp"
#include "frf/receptance.hpp"
#include "model/model.hpp"
#include "reduction/craig_bampton.hpp"
#include "reduction/reduced_model.hpp"

namespace bb {

// The one node of node set `point`; throws InputError when there is no such set or it is not one node.
int node_of_point(const Model& model, const std::string& point);
// The free equation of `dof`; throws InputError when it is constrained.
int free_index(const Model& model, const FreeSystem& system, const PointDof& dof);
// Rayleigh coefficients fitted to the two (frequency, zeta) pairs of `damping`.
RayleighCoefficients rayleigh_of(const FrfDamping& damping);

// A reduced model as `rom` asks: Craig-Bampton of `system` (the free system of `model`) on its
// masters (through the model cache in `cache`, when given), read from its file, or its matrices.
// Throws InputError for unknown or constrained points.
ReducedModel build_reduced_model(const Model& model, const FreeSystem& system, const RomSpec& rom,
                                 CraigBamptonTiming* timing = nullptr, const ModelCacheSettings* cache = nullptr);
// The damping matrix of a reduced or lumped model: modal (the same ratio on each of its modes) or Rayleigh.
Eigen::MatrixXd damping_matrix(const FrfDamping& damping, const ReducedModel& model);

}  // namespace bb
