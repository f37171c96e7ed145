// Harwell-Boeing matrix files (Duff, Grimes and Lewis, "Users' Guide for the Harwell-Boeing Sparse
// Matrix Collection", 1992), the format of an Ansys HBMAT export, and the DOF map that names node and
// direction per row (Ansys HBMAT's .mapping file, or a CSV node,direction).
#pragma once
#include <Eigen/Dense>

#include <filesystem>
#include <string_view>
#include <vector>

#include "reduction/reduced_model.hpp"

namespace bb {

// The real assembled matrix of `file` (type RSA or RUA), dense, n x n: an RSA file's one triangle is
// mirrored. Throws InputError naming file:line for a header that disagrees with the data (card
// counts, entry counts, pointers), a type other than real assembled symmetric or unsymmetric, a size
// other than n, an index out of range or repeated, and an RUA matrix that is not symmetric (relative
// 1e-8 of its largest entry): stiffness and mass must be.
// `named_by` says where n came from ("the DOF map rom.mapping names 7 DOFs"), for the size message.
Eigen::MatrixXd read_harwell_boeing(const std::filesystem::path& file, Eigen::Index n, std::string_view named_by);

// The DOFs of a DOF map, one per matrix row, in order. Ansys's .mapping ("Matrix Eqn  Node  DOF"
// header, rows "1  7  UX") or a CSV with header node,direction (direction x|y|z or UX|UY|UZ); a node
// number becomes the DOF's label ("7.x"). Throws InputError naming file:line for a rotation DOF, an
// equation out of order, a repeated DOF, a malformed row.
std::vector<ReducedDof> read_dof_map(const std::filesystem::path& file);

}  // namespace bb
