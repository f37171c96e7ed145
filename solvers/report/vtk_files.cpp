#include "report/vtk_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "analysis/operating_deflection.hpp"
#include "common/constants.hpp"
#include "cyclic/cyclic_boundary.hpp"
#include "mesh/vtu_writer.hpp"
#include "report/writers.hpp"

namespace bb {
namespace vtk_files_impl {
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

// N copies of the sector, copy j turned by j 2 pi / N about z (not merged: the seams are the sector
// faces); node id j (largest id + 1) + id, and the point array "sector" = j.
Mesh whole_disk_mesh(const Mesh& sector, int sectors, std::vector<double>& sector_of_point) {
  Mesh disk;
  disk.dim = sector.dim;
  const long stride = *std::max_element(sector.node_ids.begin(), sector.node_ids.end()) + 1;
  const Eigen::Index n = sector.n_nodes();
  disk.coords.resize(n * sectors, sector.dim);
  const Eigen::MatrixXd rotation = sector_rotation(sectors, sector.dim);
  Eigen::MatrixXd turn = Eigen::MatrixXd::Identity(sector.dim, sector.dim);
  for (int j = 0; j < sectors; ++j) {
    disk.coords.middleRows(j * n, n) = sector.coords * turn.transpose();
    for (const long id : sector.node_ids) {
      disk.node_ids.push_back(j * stride + id);
      sector_of_point.push_back(j);
    }
    turn = rotation * turn;
  }
  for (const ElementBlock& b : sector.blocks) {
    ElementBlock copy{b.type, {}, {}};
    copy.conn.resize(b.conn.rows() * sectors, b.conn.cols());
    for (int j = 0; j < sectors; ++j) {
      copy.conn.middleRows(j * b.conn.rows(), b.conn.rows()) = b.conn.array() + static_cast<int>(j * n);
      for (const long id : b.ids) copy.ids.push_back(j * stride + id);
    }
    disk.blocks.push_back(std::move(copy));
  }
  return disk;
}

// The standing waves of every family of each nodal diameter k over the whole disk, one file per k:
// with the family's cosine and sine parts c, s (cyclic/cyclic_projection.hpp's u_j = Re(U e^{i k j
// 2 pi / N}), U = c + i s), sector j moves as R^j (c cos(k j 2 pi / N) - s sin(k j 2 pi / N)), and a
// quarter period later as R^j (s cos + c sin): continuous across every seam (tests/vtk).
void write_disk(const CyclicModalOutcome& o, const Mesh& sector, const fs::path& out, RunRecord& run) {
  std::vector<double> sector_of_point;
  const Mesh disk = whole_disk_mesh(sector, o.sectors, sector_of_point);
  const int dim = sector.dim;
  const Eigen::Index n = sector.n_nodes();
  const Eigen::MatrixXd rotation = sector_rotation(o.sectors, dim);
  // A sector's free-DOF vector as its nodes' displacements (constrained DOFs 0).
  auto nodal = [&](const Eigen::VectorXd& free) {
    Eigen::MatrixXd u = Eigen::MatrixXd::Zero(n, dim);
    for (Eigen::Index node = 0; node < n; ++node)
      for (int d = 0; d < dim; ++d)
        if (const int eq = o.dofs.equation[static_cast<size_t>(node * dim + d)]; eq >= 0) u(node, d) = free[eq];
    return u;
  };
  for (const NodalDiameterModes& nd : o.diameters) {
    VtkContent c;
    c.point_arrays.push_back(
        {"sector",
         Eigen::Map<const Eigen::VectorXd>(sector_of_point.data(), static_cast<Eigen::Index>(sector_of_point.size())),
         {}});
    for (Eigen::Index f = 0; f < nd.frequencies_hz.size(); ++f) {
      const Eigen::MatrixXd cosine = nodal(nd.cosine.col(f));
      const Eigen::MatrixXd sine = nd.pairs ? nodal(nd.sine.col(f)) : Eigen::MatrixXd::Zero(n, dim);
      for (const bool sine_wave : {false, true}) {
        if (sine_wave && !nd.pairs) continue;
        Eigen::MatrixXd u(n * o.sectors, dim);
        Eigen::MatrixXd turn = Eigen::MatrixXd::Identity(dim, dim);
        for (int j = 0; j < o.sectors; ++j) {
          const double angle = kTwoPi * nd.nodal_diameter * j / o.sectors;
          const Eigen::MatrixXd local = sine_wave ? Eigen::MatrixXd(sine * std::cos(angle) + cosine * std::sin(angle))
                                                  : Eigen::MatrixXd(cosine * std::cos(angle) - sine * std::sin(angle));
          u.middleRows(j * n, n) = local * turn.transpose();
          turn = rotation * turn;
        }
        c.point_arrays.push_back({fmt::format("family{}_{}", f + 1, sine_wave ? "sin" : "cos"), u,
                                  std::vector<std::string>(kAxes, kAxes + dim)});
      }
    }
    c.field_arrays.push_back(
        {"frequency_hz", {nd.frequencies_hz.data(), nd.frequencies_hz.data() + nd.frequencies_hz.size()}});
    c.field_arrays.push_back({"nodal_diameter", {static_cast<double>(nd.nodal_diameter)}});
    const std::string name = fmt::format("vtk/disk_nd{}.vtu", nd.nodal_diameter);
    write_vtu(out / name, disk, c);
    run.tables.push_back(name);
  }
}

// A forced response's operating deflection at each peak of the full model (at the sweep's frequency
// nearest the peak, where the sweep has its value): real and imaginary parts in vtk/ods.vtu, and one
// period of the first peak's motion as 16 frames (vtk/ods_peak<key>.pvd) to animate. False when the
// analysis has no full model or no peak.
bool write_deflections(const FrfSpec& spec, const FrfOutcome& frf, const ResultTables& tables, const Model& model,
                       const fs::path& out, RunRecord& run) {
  const auto peaks = tables.find("peaks_full");
  const auto sweep = tables.find("frf");
  if (!frf.full_modal || peaks == tables.end() || sweep == tables.end() || peaks->second.values.rows() == 0)
    return false;
  const Eigen::VectorXd grid = sweep->second.values.col(*sweep->second.column_index("frequency_hz"));
  const Eigen::Index at_hz = *peaks->second.column_index("frequency_hz");
  std::vector<double> hz, keys;
  for (Eigen::Index p = 0; p < peaks->second.values.rows(); ++p) {
    Eigen::Index nearest = 0;
    (grid.array() - peaks->second.values(p, at_hz)).abs().minCoeff(&nearest);
    hz.push_back(grid[nearest]);
    keys.push_back(peaks->second.values(p, 0));
  }
  const std::vector<Eigen::MatrixXcd> deflections = operating_deflections(model, spec, *frf.full_modal, hz);
  const int dim = model.mesh.dim;
  const std::vector<std::string> axes(kAxes, kAxes + dim);
  VtkContent c;
  for (size_t p = 0; p < hz.size(); ++p) {
    c.point_arrays.push_back({fmt::format("peak{}_re", std::lround(keys[p])), deflections[p].real(), axes});
    c.point_arrays.push_back({fmt::format("peak{}_im", std::lround(keys[p])), deflections[p].imag(), axes});
  }
  c.field_arrays.push_back({"frequency_hz", hz});
  c.field_arrays.push_back({"peak", keys});
  write_vtu(out / "vtk" / "ods.vtu", model.mesh, c);
  run.tables.push_back("vtk/ods.vtu");
  constexpr int kFrames = 16;
  const std::string stem = fmt::format("ods_peak{}", std::lround(keys.front()));
  fs::create_directories(out / "vtk" / stem);
  std::vector<std::pair<double, std::string>> steps;
  for (int i = 0; i < kFrames; ++i) {
    const double theta = kTwoPi * i / kFrames;
    const std::complex<double> turn = std::polar(1.0, theta);
    const Eigen::MatrixXd u = (deflections.front() * turn).real();
    const std::string frame = fmt::format("{}/frame_{:02}.vtu", stem, i);
    write_vtu(out / "vtk" / frame, model.mesh, {{{"displacement", u, axes}}, {}});
    steps.emplace_back(theta / (kTwoPi * hz.front()), frame);
  }
  write_pvd(out / "vtk" / (stem + ".pvd"), steps);
  run.tables.push_back("vtk/" + stem + ".pvd");
  return true;
}

}  // namespace
}  // namespace vtk_files_impl

void write_vtk_files(const AnalysisSpec& spec, const AnalysisResults& results, const Model& model,
                     const std::filesystem::path& out, RunRecord& run) {
  using namespace vtk_files_impl;  // this file's helpers, in this scope only (unity builds)
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
  if (const auto* frf = std::get_if<FrfOutcome>(&results.outcome))
    written = write_deflections(std::get<FrfSpec>(spec), *frf, results.tables, model, out, run);
  if (const auto* cyclic = std::get_if<CyclicModalOutcome>(&results.outcome)) {
    write_disk(*cyclic, mesh, out, run);
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
