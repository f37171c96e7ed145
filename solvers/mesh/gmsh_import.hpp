// Gmsh .msh format 4.1 (ASCII) import: nodes, volume (or surface) elements, physical groups.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace bb {

struct GmshMesh {
  Mesh mesh;  // dim 3 when the file has 3D elements, else 2; node ids = Gmsh node tags
  // Physical group name (or "physical_<tag>" when unnamed) -> internal node indices, sorted,
  // of every node of every element (of any dimension) in that group.
  std::map<std::string, std::vector<int>> node_groups;
};

// Supported element types: 2 (3-node triangle -> cst), 3 (4-node quad -> q4), 5 (8-node hex ->
// hex8 or hex8i as `linear_hex` says), 17 (20-node hex, reordered to the Ansys/CalculiX order of
// mesh/mesh.hpp). Elements of the highest dimension present form the mesh; lower-dimensional
// ones only feed node_groups. Other element types in the mesh dimension, a version other than
// 4.1, binary files, or undefined node tags throw InputError naming the file and line.
GmshMesh read_gmsh_msh41(const std::filesystem::path& file, ElementType linear_hex = ElementType::hex8);

}  // namespace bb
