// The load vector of a model over all global DOFs (node * dim + dir) [N]: its nodal loads split
// over their sets, its distributed loads integrated over boundary edges / faces (fe/surface_load),
// its body loads through the element masses.
#pragma once
#include <Eigen/Dense>

#include "model/model.hpp"

namespace bb {

// Throws InputError for an unknown set, a consistent split over a set that holds no element edge, or
// a distributed load on a set that holds no boundary edge (2D) / face (3D).
Eigen::VectorXd load_vector(const Model& model);

// The parts of it, each over all global DOFs.
Eigen::VectorXd surface_load_vector(const Mesh& mesh, double thickness, const SurfaceLoad& load,
                                    const std::vector<int>& set_nodes);
Eigen::VectorXd body_load_vector(const Mesh& mesh, const fe::PlaneSection& section, const BodyLoad& load);

}  // namespace bb
