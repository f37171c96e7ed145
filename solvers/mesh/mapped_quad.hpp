// Structured mesh of a quadrilateral domain mapped bilinearly from four corners.
#pragma once
#include <array>

#include "mesh/mesh.hpp"

namespace bb {

enum class NodeNumbering {
  rows,        // row by row from the first corner's edge, each row from corner 1 towards corner 2
  serpentine,  // like rows, but every second row runs back (the thesis's Tables II and IV)
};

enum class TriangleDiagonal {
  bottom_left_to_top_right,  // each cell split along corner 1 -> corner 3 of the cell
  bottom_right_to_top_left,  // each cell split along corner 2 -> corner 4 of the cell
  alternating,               // the two patterns in a checkerboard
};

struct MappedQuadSpec {
  std::array<Eigen::Vector2d, 4> corners;  // counterclockwise: bottom-left, bottom-right, top-right, top-left
  int nx = 1;                              // divisions along corner 1 -> corner 2
  int ny = 1;                              // divisions along corner 1 -> corner 4
  ElementType element = ElementType::q4;
  TriangleDiagonal diagonal = TriangleDiagonal::bottom_left_to_top_right;
  NodeNumbering numbering = NodeNumbering::rows;
  long first_node_id = 1;
  long first_element_id = 1;
};

// Throws std::invalid_argument for non-positive divisions.
Mesh generate_mapped_quad(const MappedQuadSpec& spec);

}  // namespace bb
