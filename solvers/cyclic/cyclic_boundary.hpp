// The cyclic boundary of one sector of a rotationally periodic structure about the z axis: each
// node of the right face is the image of a node of the left face under the sector rotation by
// 2 pi / N, and in a travelling wave of nodal diameter k the right face moves as its left
// neighbour's face does, turned by the rotation and shifted in phase by k 2 pi / N.
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "assembly/dof_map.hpp"
#include "mesh/mesh.hpp"

namespace bb {

// Node pairs: right[i] is left[i] turned by the sector angle.
struct SectorFaces {
  std::vector<int> left, right;
};

// Pairs every node of `right` with the node of `left` it is the image of, within `tolerance` [m].
// Throws InputError naming the first node that has no partner, a node on both faces (on the axis)
// or faces of different sizes; `what` prefixes the messages (e.g. the case key).
SectorFaces pair_sector_faces(const Mesh& mesh, const std::vector<int>& left, const std::vector<int>& right,
                              int sectors, double tolerance, const std::string& what);

// The rotation by 2 pi / N about z, in the mesh's dimension (3: Cartesian x, y, z).
Eigen::MatrixXd sector_rotation(int sectors, int dim);

// The same pairs at the level of free equations: per node pair, `dim` left and right equations
// (-1 where the DOF is constrained). u_right = rotation * u_left for an in-phase (ND 0) motion.
struct CyclicDofs {
  int sectors = 0;
  int dim = 3;
  Eigen::MatrixXd rotation;
  std::vector<int> left, right;  // dim entries per node pair
};

// Throws InputError when a paired DOF is constrained on one face and free on the other (the
// constraints of a sector must be cyclic themselves).
CyclicDofs cyclic_dofs(const Mesh& mesh, const DofMap& dofs, const SectorFaces& faces, int sectors);

}  // namespace bb
