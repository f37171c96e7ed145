#include "report/vtk_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "analysis/operating_deflection.hpp"
#include "assembly/dof_map.hpp"
#include "common/constants.hpp"
#include "cyclic/cyclic_boundary.hpp"
#include "forced/hbm_level_system.hpp"
#include "friction/jenkins.hpp"
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
  for (const NodalDiameterModes& nd : o.diameters) {
    VtkContent c;
    c.point_arrays.push_back(
        {"sector",
         Eigen::Map<const Eigen::VectorXd>(sector_of_point.data(), static_cast<Eigen::Index>(sector_of_point.size())),
         {}});
    for (Eigen::Index f = 0; f < nd.frequencies_hz.size(); ++f) {
      const Eigen::MatrixXd cosine = nodal_rows(o.dofs, nd.cosine.col(f));
      const Eigen::MatrixXd sine = nd.pairs ? nodal_rows(o.dofs, nd.sine.col(f)) : Eigen::MatrixXd::Zero(n, dim);
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

// One period of a motion of harmonics `coefficients` (nodes x dim each: c0, a1, b1, ...) as 16 frames
// in a .pvd (vtk/<stem>.pvd, frames in vtk/<stem>/), u(theta) = c0 + sum a_h cos(h theta) + b_h sin(h theta).
void write_period(const Mesh& mesh, const std::vector<Eigen::MatrixXd>& coefficients, double hz,
                  const std::string& stem, const fs::path& out, RunRecord& run) {
  constexpr int kFrames = 16;
  const std::vector<std::string> axes(kAxes, kAxes + mesh.dim);
  fs::create_directories(out / "vtk" / stem);
  std::vector<std::pair<double, std::string>> steps;
  for (int i = 0; i < kFrames; ++i) {
    const double theta = kTwoPi * i / kFrames;
    Eigen::MatrixXd u = coefficients.front();
    for (size_t h = 1; 2 * h < coefficients.size(); ++h)
      u += coefficients[2 * h - 1] * std::cos(static_cast<double>(h) * theta) +
           coefficients[2 * h] * std::sin(static_cast<double>(h) * theta);
    const std::string frame = fmt::format("{}/frame_{:02}.vtu", stem, i);
    write_vtu(out / "vtk" / frame, mesh, {{{"displacement", u, axes}}, {}});
    steps.emplace_back(theta / (kTwoPi * hz), frame);
  }
  write_pvd(out / "vtk" / (stem + ".pvd"), steps);
  run.tables.push_back("vtk/" + stem + ".pvd");
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
  // u = Re(U e^{i theta}): a1 = Re U, b1 = -Im U.
  const Eigen::MatrixXcd& u = deflections.front();
  write_period(model.mesh, {Eigen::MatrixXd::Zero(u.rows(), u.cols()), u.real(), -u.imag()}, hz.front(),
               fmt::format("ods_peak{}", std::lround(keys.front())), out, run);
  return true;
}

// Where each contact of a harmonic balance acts: the mean position of the node sets its tangential
// DOFs name ("tip.y" -> set "tip"); nullopt for a contact on none (modal coordinates, a damper).
std::optional<Eigen::Vector3d> contact_position(const friction::ContactElement& contact,
                                                const std::vector<std::string>& dof_names, const Model& model) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (Eigen::Index d = 0; d < contact.tangential.size(); ++d) {
    if (contact.tangential[d] == 0.0 || static_cast<size_t>(d) >= dof_names.size()) continue;
    const std::string& name = dof_names[static_cast<size_t>(d)];
    const auto set = model.node_sets.find(name.substr(0, name.rfind('.')));
    if (set == model.node_sets.end()) continue;
    for (const int node : set->second) {
      sum.head(model.mesh.dim) += model.mesh.coords.row(node).transpose();
      ++count;
    }
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

// The contacts of the first peak over its period, one frame per AFT sample (vtk/contacts_fe1_peak1.pvd):
// points with the tangential and normal forces [N], the relative tangential displacement [m] and
// the state (0 stick, 1 and -1 slip along +u and -u, 2 lift-off), the same samples contact_states.csv
// counts. False when no contact has a place on the mesh.
bool write_contact_frames(const HbmOutcome& o, const Model& model, const HbmPeak& peak, const fs::path& out,
                          RunRecord& run) {
  std::vector<size_t> located;
  Eigen::MatrixXd points(0, 3);
  for (size_t c = 0; c < o.prepared.model.contacts.size() && c < peak.solution.contacts.size(); ++c)
    if (const auto x = contact_position(o.prepared.model.contacts[c], o.prepared.dof_names, model)) {
      located.push_back(c);
      points.conservativeResize(points.rows() + 1, 3);
      points.row(points.rows() - 1) = x->transpose();
    }
  if (located.empty()) return false;
  const std::string stem = "contacts_fe1_peak1";
  fs::create_directories(out / "vtk" / stem);
  const Eigen::Index samples = peak.solution.contacts[located.front()].t.size();
  std::vector<std::pair<double, std::string>> steps;
  for (Eigen::Index k = 0; k < samples; ++k) {
    const auto n = static_cast<Eigen::Index>(located.size());
    Eigen::VectorXd t(n), normal(n), u(n), state(n), index(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const friction::AftResult& a = peak.solution.contacts[located[static_cast<size_t>(i)]];
      t[i] = a.t[k];
      normal[i] = a.n[k];
      u[i] = a.u[k];
      const friction::ContactState s = a.state[static_cast<size_t>(k)];
      state[i] = s == friction::ContactState::stick           ? 0.0
                 : s == friction::ContactState::slip_positive ? 1.0
                 : s == friction::ContactState::slip_negative ? -1.0
                                                              : 2.0;
      index[i] = static_cast<double>(located[static_cast<size_t>(i)] + 1);
    }
    const std::string frame = fmt::format("{}/frame_{:03}.vtu", stem, k);
    write_point_vtu(out / "vtk" / frame, points,
                    {{{"tangential_force", t, {}},
                      {"normal_force", normal, {}},
                      {"relative_displacement", u, {}},
                      {"state", state, {}},
                      {"contact", index, {}}},
                     {}});
    steps.emplace_back(kTwoPi * static_cast<double>(k) / static_cast<double>(samples) / peak.solution.omega, frame);
  }
  write_pvd(out / "vtk" / (stem + ".pvd"), steps);
  run.tables.push_back("vtk/" + stem + ".pvd");
  return true;
}

// A harmonic balance's motion at each peak recovered on the mesh through the Craig-Bampton model:
// harmonic h as U_h = a_h - i b_h (u = Re(sum U_h e^{i h w t}) + c0), arrays "fe<level>_peak<k>_h<h>_re"
// and "_im" (h = 0: the static part, "_re" only) in vtk/hbm_peaks.vtu, and the first peak's period as
// frames. False when the linear model has no recovery to the mesh (a model read from a file, a
// cyclic sector) or there is no peak.
bool write_hbm_deflections(const HbmSpec& spec, const HbmOutcome& o, const Model& model, const fs::path& out,
                           RunRecord& run) {
  const ReducedModel& linear = o.prepared.linear;
  const DofMap dofs = number_dofs(model);
  if (linear.recovery.size() == 0 || linear.recovery.rows() != dofs.n_free) return false;
  const int dim = model.mesh.dim;
  const std::vector<std::string> axes(kAxes, kAxes + dim);
  VtkContent c;
  std::vector<double> hz, force, harmonics;
  std::vector<Eigen::MatrixXd> first;  // the first peak's coefficients, for its period
  const HbmPeak* first_peak = nullptr;
  for (size_t l = 0; l < o.levels.size(); ++l) {
    const HbmLevel& level = o.levels[l];
    for (size_t k = 0; k < level.peaks.size(); ++k) {
      const HbmPeak& peak = level.peaks[k];
      // The peak's own system (its H), as the sweep built it.
      const hbm::HarmonicBalance balance = level_system(o.prepared, spec, level.force, peak.harmonics, level.samples);
      const Eigen::MatrixXd q = balance.recover(peak.solution.x, peak.solution.omega);
      const Eigen::MatrixXd free = linear.recovery * q.topRows(linear.recovery.cols());
      const std::string name = fmt::format("fe{}_peak{}", l + 1, k + 1);
      std::vector<Eigen::MatrixXd> coefficients;
      for (Eigen::Index col = 0; col < free.cols(); ++col) coefficients.push_back(nodal_rows(dofs, free.col(col)));
      c.point_arrays.push_back({name + "_h0_re", coefficients.front(), axes});
      for (int h = 1; 2 * h < static_cast<int>(coefficients.size()); ++h) {
        c.point_arrays.push_back(
            {fmt::format("{}_h{}_re", name, h), coefficients[2 * static_cast<size_t>(h) - 1], axes});
        c.point_arrays.push_back({fmt::format("{}_h{}_im", name, h), -coefficients[2 * static_cast<size_t>(h)], axes});
      }
      hz.push_back(peak.frequency_hz);
      force.push_back(level.force);
      harmonics.push_back(peak.harmonics);
      if (first.empty()) {
        first = std::move(coefficients);
        first_peak = &peak;
      }
    }
  }
  if (first.empty()) return false;
  c.field_arrays.push_back({"frequency_hz", hz});
  c.field_arrays.push_back({"force_n", force});
  c.field_arrays.push_back({"harmonics", harmonics});
  write_vtu(out / "vtk" / "hbm_peaks.vtu", model.mesh, c);
  run.tables.push_back("vtk/hbm_peaks.vtu");
  write_period(model.mesh, first, hz.front(), "hbm_fe1_peak1", out, run);
  write_contact_frames(o, model, *first_peak, out, run);
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
  if (const auto* hbm = std::get_if<HbmOutcome>(&results.outcome))
    written = write_hbm_deflections(std::get<HbmSpec>(spec), *hbm, model, out, run);
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
