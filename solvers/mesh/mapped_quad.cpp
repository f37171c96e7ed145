#include "mesh/mapped_quad.hpp"

#include <stdexcept>

namespace bb {

Mesh generate_mapped_quad(const MappedQuadSpec& spec) {
  if (spec.nx < 1 || spec.ny < 1) throw std::invalid_argument("nx and ny must be >= 1");
  const int nx = spec.nx, ny = spec.ny;
  const int n_nodes = (nx + 1) * (ny + 1);
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords.resize(n_nodes, 2);
  mesh.node_ids.resize(n_nodes);
  auto grid = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double s = static_cast<double>(i) / nx, r = static_cast<double>(j) / ny;
      const Eigen::Vector2d p = (1 - s) * (1 - r) * spec.corners[0] + s * (1 - r) * spec.corners[1] +
                                s * r * spec.corners[2] + (1 - s) * r * spec.corners[3];
      const int n = grid(i, j);
      mesh.coords.row(n) = p.transpose();
      const bool reversed = spec.numbering == NodeNumbering::serpentine && (j % 2 == 1);
      const int position = j * (nx + 1) + (reversed ? nx - i : i);
      mesh.node_ids[n] = spec.first_node_id + position;
    }
  }
  ElementBlock block;
  block.type = spec.element;
  const bool tri = spec.element == ElementType::cst;
  const int n_elem = nx * ny * (tri ? 2 : 1);
  block.conn.resize(n_elem, tri ? 3 : 4);
  block.ids.resize(n_elem);
  int e = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int c1 = grid(i, j), c2 = grid(i + 1, j), c3 = grid(i + 1, j + 1), c4 = grid(i, j + 1);
      if (!tri) {
        block.conn.row(e) << c1, c2, c3, c4;
        block.ids[e] = spec.first_element_id + e;
        ++e;
        continue;
      }
      bool along_13 = spec.diagonal == TriangleDiagonal::bottom_left_to_top_right;
      if (spec.diagonal == TriangleDiagonal::alternating) along_13 = (i + j) % 2 == 0;
      if (along_13) {
        block.conn.row(e) << c1, c2, c3;
        block.conn.row(e + 1) << c1, c3, c4;
      } else {
        block.conn.row(e) << c1, c2, c4;
        block.conn.row(e + 1) << c2, c3, c4;
      }
      block.ids[e] = spec.first_element_id + e;
      block.ids[e + 1] = spec.first_element_id + e + 1;
      e += 2;
    }
  }
  mesh.blocks.push_back(std::move(block));
  mesh.rebuild_index();
  return mesh;
}

}  // namespace bb
