#include "report/vtk_files.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "mesh/vtu_writer.hpp"
#include "report/writers.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

constexpr const char* kAxes[] = {"x", "y", "z"};

// A table keyed by node whose rows are the mesh's nodes in order: the analysis's field on the mesh.
bool nodal(const ResultTable& t, const Mesh& mesh) {
  if (t.columns.empty() || t.columns[0] != "node" || t.values.rows() != mesh.n_nodes()) return false;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (t.values(n, 0) != static_cast<double>(mesh.node_ids[static_cast<size_t>(n)])) return false;
  return true;
}

void add_table(const ResultTable& t, int dim, VtkContent& c) {
  for (size_t k = 1; k < t.columns.size(); ++k)
    c.point_arrays.push_back({t.name + "." + t.columns[k], t.values.col(static_cast<Eigen::Index>(k)), {}});
  // ux, uy(, uz) side by side: also one vector, the one ParaView's Warp By Vector takes.
  const auto ux = t.column_index("ux");
  if (!ux || *ux + dim > static_cast<int>(t.columns.size()) || t.columns[static_cast<size_t>(*ux + 1)] != "uy") return;
  std::vector<std::string> names(kAxes, kAxes + dim);
  c.point_arrays.push_back({t.name, t.values.middleCols(*ux, dim), names});
}

// Modes as vectors over the nodes, and the same numbers as a table (node, mode<k>_ux, ...).
void write_modes(const ModalResult& modal, const Mesh& mesh, const fs::path& out, RunRecord& run) {
  VtkContent c;
  const int dim = mesh.dim;
  ResultTable t;
  t.name = "mode_shapes";
  t.columns = {"node"};
  t.values.resize(mesh.n_nodes(), 1 + dim * static_cast<Eigen::Index>(modal.shapes.size()));
  for (int n = 0; n < mesh.n_nodes(); ++n) t.values(n, 0) = static_cast<double>(mesh.node_ids[static_cast<size_t>(n)]);
  for (size_t k = 0; k < modal.shapes.size(); ++k) {
    c.point_arrays.push_back(
        {fmt::format("mode_{}", k + 1), modal.shapes[k], std::vector<std::string>(kAxes, kAxes + dim)});
    for (int d = 0; d < dim; ++d) {
      t.columns.push_back(fmt::format("mode{}_u{}", k + 1, kAxes[d]));
      t.values.col(1 + dim * static_cast<Eigen::Index>(k) + d) = modal.shapes[k].col(d);
    }
  }
  c.field_arrays.push_back(
      {"frequency_hz", {modal.frequencies_hz.data(), modal.frequencies_hz.data() + modal.frequencies_hz.size()}});
  for (Eigen::Index d = 0; d < modal.effective_mass_fraction.cols(); ++d) {
    const Eigen::VectorXd f = modal.effective_mass_fraction.col(d);
    c.field_arrays.push_back({fmt::format("effective_mass_fraction_{}", kAxes[d]), {f.data(), f.data() + f.size()}});
  }
  write_vtu(out / "vtk" / "modes.vtu", mesh, c);
  run.tables.push_back("vtk/modes.vtu");
  write_result_csv(t, out, run);
}

}  // namespace

void write_vtk_files(const AnalysisSpec& spec, const AnalysisResults& results, const Model& model, const fs::path& out,
                     RunRecord& run) {
  const Mesh& mesh = model.mesh;
  const std::string analysis = std::visit([](const auto& s) { return std::string(analysis_type_name(s)); }, spec);
  if (mesh.n_nodes() == 0) {
    run.warnings.push_back(
        fmt::format("vtk: the {} analysis has no mesh (its model is given by matrices): no .vtu "
                    "written",
                    analysis));
    return;
  }
  fs::create_directories(out / "vtk");
  bool written = false;
  if (const auto* modal = std::get_if<ModalOutcome>(&results.outcome)) {
    write_modes(modal->modal, mesh, out, run);
    written = true;
  }
  VtkContent fields;
  for (const auto& [name, table] : results.tables)
    if (nodal(table, mesh)) add_table(table, mesh.dim, fields);
  if (!fields.point_arrays.empty()) {
    write_vtu(out / "vtk" / "fields.vtu", mesh, fields);
    run.tables.push_back("vtk/fields.vtu");
    written = true;
  }
  if (!written) {
    write_vtu(out / "vtk" / "mesh.vtu", mesh, {});
    run.tables.push_back("vtk/mesh.vtu");
    run.warnings.push_back(
        fmt::format("vtk: the {} analysis has no field over the mesh's nodes (its results are the "
                    "CSV tables); wrote the mesh alone, vtk/mesh.vtu",
                    analysis));
  }
}

}  // namespace bb
