// Sparsity pattern of a nodal finite-element matrix, built from element connectivity before any
// value is computed, so element matrices are added in place (no triplet list: a triplet list
// costs several times the final matrix in memory, see bench/README.md).
#pragma once
#include <Eigen/Sparse>

#include <vector>

#include "mesh/mesh.hpp"

namespace bb {

class NodalPattern {
 public:
  explicit NodalPattern(const Mesh& mesh);

  // A zero matrix (all nodal DOFs, global order node * dim + dir) with the full pattern.
  Eigen::SparseMatrix<double> zero_matrix() const;

  // Adds an element matrix (element DOF order: node a, direction d -> a * dim + d) into `m`,
  // which must come from zero_matrix().
  template <typename ElementMatrix>
  void add(Eigen::SparseMatrix<double>& m, const int* nodes, int n_nodes, const ElementMatrix& ke) const {
    const int dim = dim_;
    double* values = m.valuePtr();
    const int* outer = m.outerIndexPtr();
    for (int a = 0; a < n_nodes; ++a) {
      const int col_node = nodes[a];
      const int* adj_begin = adjacency_.data() + adjacency_start_[col_node];
      const int* adj_end = adjacency_.data() + adjacency_start_[col_node + 1];
      for (int c = 0; c < n_nodes; ++c) {
        const int slot = static_cast<int>(std::lower_bound(adj_begin, adj_end, nodes[c]) - adj_begin);
        for (int dc = 0; dc < dim; ++dc) {
          double* column = values + outer[col_node * dim + dc] + slot * dim;
          for (int dr = 0; dr < dim; ++dr) column[dr] += ke(c * dim + dr, a * dim + dc);
        }
      }
    }
  }

 private:
  int dim_ = 2;
  int n_nodes_ = 0;
  std::vector<long> adjacency_start_;  // CSR of the node graph, self included, sorted
  std::vector<int> adjacency_;
};

}  // namespace bb
