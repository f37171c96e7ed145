#include "assembly/sparsity.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace bb {

NodalPattern::NodalPattern(const Mesh& mesh) : dim_(mesh.dim), n_nodes_(mesh.n_nodes()) {
  // Node -> elements, then node -> neighbouring nodes through those elements.
  std::vector<long> count(static_cast<size_t>(n_nodes_) + 1, 0);
  for (const auto& b : mesh.blocks)
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (Eigen::Index a = 0; a < b.conn.cols(); ++a) ++count[static_cast<size_t>(b.conn(e, a)) + 1];
  for (size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
  std::vector<std::pair<int, int>> node_elements(static_cast<size_t>(count.back()));  // (block, element)
  std::vector<long> fill(count.begin(), count.end() - 1);
  for (size_t bi = 0; bi < mesh.blocks.size(); ++bi) {
    const auto& b = mesh.blocks[bi];
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (Eigen::Index a = 0; a < b.conn.cols(); ++a)
        node_elements[static_cast<size_t>(fill[static_cast<size_t>(b.conn(e, a))]++)] = {static_cast<int>(bi),
                                                                                         static_cast<int>(e)};
  }
  adjacency_start_.assign(static_cast<size_t>(n_nodes_) + 1, 0);
  std::vector<int> scratch;
  for (int n = 0; n < n_nodes_; ++n) {
    scratch.clear();
    scratch.push_back(n);
    for (long k = count[static_cast<size_t>(n)]; k < count[static_cast<size_t>(n) + 1]; ++k) {
      const auto [bi, e] = node_elements[static_cast<size_t>(k)];
      const auto& conn = mesh.blocks[static_cast<size_t>(bi)].conn;
      for (Eigen::Index a = 0; a < conn.cols(); ++a) scratch.push_back(conn(e, a));
    }
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    adjacency_.insert(adjacency_.end(), scratch.begin(), scratch.end());
    adjacency_start_[static_cast<size_t>(n) + 1] = static_cast<long>(adjacency_.size());
  }
  const long nnz = static_cast<long>(adjacency_.size()) * dim_ * dim_;
  if (nnz > std::numeric_limits<int>::max()) throw std::length_error("matrix has more nonzeros than an int can index");
}

Eigen::SparseMatrix<double> NodalPattern::zero_matrix() const {
  const int n = n_nodes_ * dim_;
  Eigen::SparseMatrix<double> m(n, n);
  const long nnz = static_cast<long>(adjacency_.size()) * dim_ * dim_;
  m.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = m.outerIndexPtr();
  int* inner = m.innerIndexPtr();
  long pos = 0;
  for (int node = 0; node < n_nodes_; ++node) {
    for (int d = 0; d < dim_; ++d) {
      outer[node * dim_ + d] = static_cast<int>(pos);
      for (long k = adjacency_start_[static_cast<size_t>(node)]; k < adjacency_start_[static_cast<size_t>(node) + 1];
           ++k)
        for (int dr = 0; dr < dim_; ++dr) inner[pos++] = adjacency_[static_cast<size_t>(k)] * dim_ + dr;
    }
  }
  outer[n] = static_cast<int>(pos);
  std::fill(m.valuePtr(), m.valuePtr() + nnz, 0.0);
  return m;
}

}  // namespace bb
