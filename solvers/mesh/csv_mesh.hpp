// Meshes from two CSV files, nodes (id,x,y[,z]) and elements (id,n1..nN), the lists the thesis
// exported from Ansys to SAMS/2000 (Figs 2.19-2.20).
#pragma once
#include <filesystem>

#include "mesh/mesh.hpp"

namespace bb {

// Throws InputError naming the file and line of a bad number, a duplicate id, an unknown node, an
// element listed clockwise (plane meshes) or a column count that does not fit `element`.
Mesh read_csv_mesh(const std::filesystem::path& nodes, const std::filesystem::path& elements, ElementType element);

}  // namespace bb
