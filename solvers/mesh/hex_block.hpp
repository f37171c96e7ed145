// Structured hexahedral meshes of blocks mapped trilinearly from 8 corners, and the merging of
// several blocks (or any meshes) at coincident nodes: the thesis "glues" bodies that way.
#pragma once
#include <array>
#include <vector>

#include "mesh/mesh.hpp"

namespace bb {

struct HexBlockSpec {
  // Corners in hex8 node order: 1-4 the face at the first end of the third direction,
  // counterclockwise seen from the other end; 5-8 above 1-4.
  std::array<Eigen::Vector3d, 8> corners;
  int nx = 1;                               // divisions along corner 1 -> 2
  int ny = 1;                               // along corner 1 -> 4
  int nz = 1;                               // along corner 1 -> 5
  ElementType element = ElementType::hex8;  // hex8, hex8i or hex20
  long first_node_id = 1;
  long first_element_id = 1;
};

// Throws std::invalid_argument for non-positive divisions or a non-solid element type.
Mesh generate_hex_block(const HexBlockSpec& spec);

// The first corner (1-8) at which the block's trilinear map has a non-positive Jacobian (the block
// is twisted, inverted or flat there), or 0 when there is none.
int inverted_corner(const std::array<Eigen::Vector3d, 8>& corners);

// Concatenates meshes and merges nodes closer than `tolerance` [m] (spatial hashing, so
// linear in the node count). Node ids are renumbered 1..n in order of first appearance and
// element ids 1..m; `node_origin` (optional) receives, for every input mesh, the new internal
// index of each of its nodes. Elements of one type are gathered into one block.
Mesh merge_meshes(const std::vector<Mesh>& parts, double tolerance,
                  std::vector<std::vector<int>>* node_origin = nullptr);

// The same without merging: coincident nodes of different parts stay distinct (bodies that touch
// without being glued, e.g. the two sides of a contact pair).
Mesh concatenate_meshes(const std::vector<Mesh>& parts, std::vector<std::vector<int>>* node_origin = nullptr);

}  // namespace bb
