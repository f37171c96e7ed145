// VTK XML output for ParaView: a mesh with arrays at its nodes (.vtu, one state) and a collection of
// such files over time (.pvd, an animation). Arrays binary (base64 inline), so a file read back gives
// the doubles written, bit for bit.
#pragma once
#include <Eigen/Dense>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace bb {

// One array over the nodes (or the points): n x components; a 2D vector is written with z = 0 so that
// ParaView warps and glyphs it.
struct VtkArray {
  std::string name;
  Eigen::MatrixXd values;
  std::vector<std::string> component_names;  // empty: ParaView's default (0, 1, 2 / X, Y, Z)
};

// Field data: arrays that belong to the whole file (a mode's frequency, participations).
struct VtkFieldArray {
  std::string name;
  std::vector<double> values;
};

struct VtkContent {
  std::vector<VtkArray> point_arrays;
  std::vector<VtkFieldArray> field_arrays;
};

// The mesh's elements as VTK cells (q4 quad, cst triangle, hex8/hex8i hexahedron, hex20 quadratic
// hexahedron: its node order is VTK's), node ids as point array "node_id", element ids as cell array
// "element_id". Throws std::runtime_error when the file cannot be written; std::invalid_argument when an
// array has not one row per node.
void write_vtu(const std::filesystem::path& file, const Mesh& mesh, const VtkContent& content);

// Points without a mesh (contact points): one vertex cell each.
void write_point_vtu(const std::filesystem::path& file, const Eigen::MatrixXd& points, const VtkContent& content);

// A ParaView collection: each (time, file relative to the .pvd) a step of the animation.
void write_pvd(const std::filesystem::path& file, const std::vector<std::pair<double, std::string>>& steps);

}  // namespace bb
