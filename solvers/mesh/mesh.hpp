// Mesh: nodes with the user's ids, and blocks of elements of one type each.
// Internal code indexes nodes 0..n-1; ids are kept only to talk to the user.
#pragma once
#include <Eigen/Dense>

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace bb {

// Node order inside an element follows Ansys/CalculiX: q4 and cst counterclockwise; hex8 nodes
// 1-4 on the bottom face (zeta = -1) counterclockwise seen from +zeta, 5-8 above them; hex20 adds
// the mid-edge nodes 9-12 (edges 1-2, 2-3, 3-4, 4-1), 13-16 (5-6, 6-7, 7-8, 8-5), 17-20 (1-5, 2-6, 3-7, 4-8).
enum class ElementType {
  q4,     // plane-stress bilinear quadrilateral
  cst,    // plane-stress constant-strain triangle
  hex8,   // trilinear hexahedron, 2x2x2 Gauss
  hex8i,  // hex8 with incompatible (bubble) modes, as Ansys SOLID45 by default
  hex20,  // serendipity hexahedron, 3x3x3 Gauss (Ansys SOLID95, CalculiX C3D20)
};

int element_dimension(ElementType type);

int nodes_per_element(ElementType type);
std::string_view element_name(ElementType type);

struct ElementBlock {
  ElementType type = ElementType::q4;
  std::vector<long> ids;                                                     // user element ids
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
