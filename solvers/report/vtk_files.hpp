// ParaView output of a run ([case] vtk = true or run --vtk): the model's mesh with the run's fields at
// its nodes, under out/vtk/.
#pragma once
#include <filesystem>

#include "analysis/run_analysis.hpp"
#include "model/model.hpp"
#include "report/run_record.hpp"

namespace bb {

// vtk/fields.vtu: every result table keyed by node with one row per mesh node (displacements,
// stresses and strains with their von Mises and principal values, a mode's stresses), each column a
// point array "<table>.<column>", displacement columns also as the vector "<table>" to warp by.
// vtk/modes.vtu (modal): one vector per mode "mode_<k>", field data frequency_hz and the effective
// mass fractions; mode_shapes.csv holds the same numbers as a table. An analysis with no field on
// the mesh gets the mesh alone (vtk/mesh.vtu) and a warning saying so; a model without a mesh a
// warning and no file. Files are listed in run.tables.
void write_vtk_files(const AnalysisSpec& spec, const AnalysisResults& results, const Model& model,
                     const std::filesystem::path& out, RunRecord& run);

}  // namespace bb
