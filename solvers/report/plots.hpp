// SVG plots drawn by gnuplot (Debian package gnuplot-nox). Data and script are kept next to
// the SVG under plots/, so every figure can be redrawn or restyled by hand.
#pragma once
#include <filesystem>
#include <string>

#include "mesh/mesh.hpp"
#include "report/run_record.hpp"

namespace bb {

// Undeformed (grey) and deformed (blue) mesh; the deformation is scaled to 10% of the model size.
Plot plot_deformed_mesh(const Mesh& mesh, const Eigen::MatrixXd& displacements, const std::filesystem::path& out_dir,
                        const std::string& stem, const std::string& title);

// Computed vs reference for every entry of one check, against the entry index.
Plot plot_check(const std::vector<CheckEntry>& entries, const std::string& group, const std::filesystem::path& out_dir,
                const std::string& stem);

// Log-log error vs free DOFs, and solve time vs free DOFs.
Plot plot_refinement_error(const RefinementResult& study, const std::filesystem::path& out_dir,
                           const std::string& stem);
Plot plot_refinement_cost(const RefinementResult& study, const std::filesystem::path& out_dir, const std::string& stem);

// Log-log max frequency error vs free DOFs, one line per element type.
Plot plot_modal_refinement(const ModalRefinementResult& study, const std::filesystem::path& out_dir,
                           const std::string& stem);

}  // namespace bb
