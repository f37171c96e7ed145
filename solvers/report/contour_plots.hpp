// Colour maps of a nodal field (e.g. the von Mises stress of assembly/stress_recovery) on the
// undeformed mesh, drawn by gnuplot's pm3d: a plane mesh is filled element by element with the
// interpolation of its nodal values (bilinear on a q4, linear on a triangle, on a few sub-cells
// each); a solid shows its skin (the boundary faces) in a 3D view. SI units.
#pragma once
#include <filesystem>
#include <string>

#include "mesh/mesh.hpp"
#include "report/run_record.hpp"

namespace bb {

// `values`: one per node. `unit`: shown after the title, e.g. "Pa".
Plot plot_nodal_contour(const Mesh& mesh, const Eigen::VectorXd& values, const std::string& unit,
                        const std::filesystem::path& out_dir, const std::string& stem, const std::string& title);

}  // namespace bb
