// Mesh: nodes with the user's ids, and blocks of elements of one type each.
// Internal code indexes nodes 0..n-1; ids are kept only to talk to the user.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace bb {

enum class ElementType { q4, cst };

int nodes_per_element(ElementType type);
std::string_view element_name(ElementType type);

struct ElementBlock {
  ElementType type = ElementType::q4;
  std::vector<long> ids;                                                    // user element ids
  Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> conn;  // internal node indices
};

struct Mesh {
  int dim = 2;
  std::vector<long> node_ids;  // user node id of each internal node
  Eigen::MatrixXd coords;      // n_nodes x dim [m]
  std::vector<ElementBlock> blocks;

  int n_nodes() const { return static_cast<int>(node_ids.size()); }
  int n_elements() const;
  // Internal index of a user node id, or -1.
  int index_of(long node_id) const;
  void rebuild_index();

 private:
  std::unordered_map<long, int> index_;
};

}  // namespace bb
