// The nodal coordinates of one element, the input of every element kernel in fe/.
#pragma once
#include <Eigen/Dense>

#include "mesh/mesh.hpp"

namespace bb {

// Rows: the element's N nodes in connectivity order; columns: the first D coordinates.
template <int N, int D>
Eigen::Matrix<double, N, D> element_coords(const Mesh& mesh, const int* nodes) {
  Eigen::Matrix<double, N, D> xyz;
  for (int a = 0; a < N; ++a) xyz.row(a) = mesh.coords.row(nodes[a]).template head<D>();
  return xyz;
}

}  // namespace bb
