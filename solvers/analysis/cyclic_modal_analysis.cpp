#include "analysis/cyclic_modal_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "assembly/free_system.hpp"
#include "common/errors.hpp"
#include "common/parallel_indices.hpp"
#include "common/seconds_since.hpp"
#include "cyclic/whole_disk.hpp"
#include "linalg/blas_threads.hpp"
#include "linalg/inertia.hpp"

namespace bb {
namespace {

const std::vector<int>& face_set(const Model& model, const std::string& name, const CyclicModalSpec& spec) {
  const auto it = model.node_sets.find(name);
  if (it == model.node_sets.end() || it->second.empty())
    throw InputError(
        fmt::format("{}: cyclic face set '{}' is not a node set of the model (or has no node)", spec.at.where(), name));
  return it->second;
}

WholeStructureCheck check_whole(const Model& sector, const CyclicModalSpec& spec, const FreeSystem& s,
                                const CyclicDofs& cyclic, const std::vector<NodalDiameterModes>& diameters) {
  const auto t0 = std::chrono::steady_clock::now();
  WholeStructureCheck w;
  // Every family of every nodal diameter below the lowest top family is known: the cut sits just
  // under it, away from that eigenvalue.
  double top = INFINITY;
  for (const NodalDiameterModes& nd : diameters) top = std::min(top, nd.frequencies_hz[spec.families - 1]);
  w.cut_hz = top * (1.0 - 1e-6);
  std::vector<std::pair<double, int>> members;
  for (const NodalDiameterModes& nd : diameters)
    for (Eigen::Index f = 0; f < nd.frequencies_hz.size(); ++f)
      if (nd.frequencies_hz[f] < w.cut_hz)
        for (int c = 0; c < (nd.pairs ? 2 : 1); ++c) members.emplace_back(nd.frequencies_hz[f], nd.nodal_diameter);
  std::sort(members.begin(), members.end());
  w.union_hz.resize(static_cast<Eigen::Index>(members.size()));
  for (size_t i = 0; i < members.size(); ++i) {
    w.union_hz[static_cast<Eigen::Index>(i)] = members[i].first;
    w.union_diameter.push_back(members[i].second);
  }
  const Model whole = whole_from_sector(sector, spec.sectors, spec.face_tolerance);
  const FreeSystem ws = assemble_free_system(whole);
  w.free_dofs = ws.dofs.n_free;
  const double sigma = std::pow(2 * std::numbers::pi * w.cut_hz, 2);
  const InertiaCount count = eigenvalues_below(ws.stiffness, ws.mass, sigma);
  if (!count.ok)
    throw SolverError(fmt::format("whole structure: Sturm count at {:.6g} Hz: {}", w.cut_hz, count.message));
  w.whole_count = count.negative;
  w.sector_count_sum = 0;
  for (const NodalDiameterModes& nd : diameters) {
    const int c = nodal_diameter_count(s.stiffness, s.mass, cyclic, nd.nodal_diameter, w.cut_hz);
    if (c < 0)
      throw SolverError(fmt::format("nodal diameter {}: Sturm count at {:.6g} Hz failed", nd.nodal_diameter, w.cut_hz));
    w.sector_count_sum += (nd.pairs ? 2 : 1) * c;
  }
  if (count.negative > 0) {
    ModalOptions options = spec.options;
    options.n_modes = count.negative;
    const ModalSolution sol = lowest_modes(ws.stiffness, ws.mass, options);
    w.whole_hz = (sol.eigenvalues.head(count.negative).cwiseMax(0.0).cwiseSqrt() / (2 * std::numbers::pi)).eval();
  }
  w.seconds = seconds_since(t0);
  return w;
}

}  // namespace

CyclicModalOutcome run_cyclic_modal(const Model& model, const CyclicModalSpec& spec) {
  const auto t0 = std::chrono::steady_clock::now();
  const FreeSystem s = assemble_free_system(model);
  const SectorFaces faces =
      pair_sector_faces(model.mesh, face_set(model, spec.left, spec), face_set(model, spec.right, spec), spec.sectors,
                        spec.face_tolerance, spec.at.where());
  const CyclicDofs cyclic = cyclic_dofs(model.mesh, s.dofs, faces, spec.sectors);
  CyclicModalOutcome o;
  o.sectors = spec.sectors;
  o.dofs = s.dofs;
  o.assembly_seconds = s.assembly_seconds + seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  // Every nodal diameter when none is listed, and for the whole-structure check.
  std::vector<int> diameters = spec.nodal_diameters;
  if (diameters.empty() || spec.whole) {
    diameters.clear();
    for (int k = 0; 2 * k <= spec.sectors; ++k) diameters.push_back(k);
  }
  // Independent eigenproblems, one per core, each with its own factorizations; on SLEPc one at a
  // time, in the same order on every rank (PETSc's solves are collective and not thread-safe).
  const bool concurrent = blas_allows_concurrent_calls() && spec.options.eigensolver != Eigensolver::slepc;
  const int threads = concurrent ? spec.threads : 1;
  o.diameters.resize(diameters.size());
  for_each_index(diameters.size(), worker_count(diameters.size(), threads), [&](std::size_t i) {
    o.diameters[i] = nodal_diameter_modes(s.stiffness, s.mass, cyclic, diameters[i], spec.families, spec.options);
  });
  o.solve_seconds = seconds_since(t1);
  if (spec.whole) o.whole = check_whole(model, spec, s, cyclic, o.diameters);
  for (int eo : spec.engine_orders) {
    const int k = excited_nodal_diameter(eo, spec.sectors);
    for (const NodalDiameterModes& nd : o.diameters)
      if (nd.nodal_diameter == k)
        for (Eigen::Index f = 0; f < nd.frequencies_hz.size(); ++f) {
          const double rpm = 60.0 * nd.frequencies_hz[f] / eo;
          if (rpm <= spec.max_speed_rpm)
            o.resonances.push_back({eo, k, static_cast<int>(f) + 1, nd.frequencies_hz[f], rpm});
        }
  }
  if (!spec.speeds_rpm.empty()) {
    std::vector<double> speeds;
    for (double rpm : spec.speeds_rpm) speeds.push_back(rpm * 2 * std::numbers::pi / 60.0);
    // With engine orders, the nodal diameters they excite: the ones a Campbell diagram is read for.
    std::vector<int> diameters_solved;
    for (const NodalDiameterModes& nd : o.diameters) {
      bool excited = spec.engine_orders.empty();
      for (int eo : spec.engine_orders)
        excited = excited || excited_nodal_diameter(eo, spec.sectors) == nd.nodal_diameter;
      if (excited) diameters_solved.push_back(nd.nodal_diameter);
    }
    o.campbell = cyclic_campbell(model, s, cyclic, speeds, diameters_solved, spec.families, spec.options,
                                 worker_count(speeds.size() * diameters_solved.size(), threads));
    o.crossings = engine_order_crossings(*o.campbell, spec.engine_orders, spec.sectors);
  }
  return o;
}

ResultTables cyclic_modal_tables(const CyclicModalOutcome& o) {
  ResultTables tables;
  auto add = [&](ResultTable t) { tables.emplace(t.name, std::move(t)); };
  const Eigen::Index families = common_families(o.diameters);
  {
    std::vector<std::string> columns = {"nodal_diameter"};
    for (Eigen::Index f = 0; f < families; ++f) columns.push_back(fmt::format("f{}_hz", f + 1));
    std::vector<std::vector<double>> rows;
    for (const NodalDiameterModes& nd : o.diameters) {
      std::vector<double> row = {static_cast<double>(nd.nodal_diameter)};
      for (Eigen::Index f = 0; f < families; ++f) row.push_back(nd.frequencies_hz[f]);
      rows.push_back(std::move(row));
    }
    add(table_from_rows("nodal_diameter_map", columns, rows));
  }
  {
    std::vector<std::vector<double>> rows;
    for (const NodalDiameterModes& nd : o.diameters)
      rows.push_back({static_cast<double>(nd.nodal_diameter), nd.pairs ? 2.0 : 1.0,
                      static_cast<double>(nd.frequencies_hz.size()), static_cast<double>(nd.sturm_count),
                      nd.sturm_frequency_hz, static_cast<double>(nd.reduced_size), static_cast<double>(nd.lanczos_runs),
                      nd.max_residual, nd.seconds});
    add(table_from_rows("cyclic_completeness",
                        {"nodal_diameter", "multiplicity", "families", "sturm_count", "sturm_frequency_hz",
                         "reduced_unknowns", "lanczos_runs", "max_residual", "seconds"},
                        rows));
  }
  if (o.whole) {
    const WholeStructureCheck& w = *o.whole;
    std::vector<std::vector<double>> u, h;
    for (Eigen::Index i = 0; i < w.union_hz.size(); ++i)
      u.push_back(
          {static_cast<double>(i + 1), w.union_hz[i], static_cast<double>(w.union_diameter[static_cast<size_t>(i)])});
    for (Eigen::Index i = 0; i < w.whole_hz.size(); ++i) h.push_back({static_cast<double>(i + 1), w.whole_hz[i]});
    add(table_from_rows("cyclic_spectrum", {"index", "frequency_hz", "nodal_diameter"}, u));
    add(table_from_rows("whole_spectrum", {"index", "frequency_hz"}, h));
    add(table_from_rows("whole_count", {"cut", "cut_hz", "whole_count", "sector_count_sum", "union_size"},
                        {{1.0, w.cut_hz, static_cast<double>(w.whole_count), static_cast<double>(w.sector_count_sum),
                          static_cast<double>(w.union_hz.size())}}));
  }
  if (!o.resonances.empty()) {
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < o.resonances.size(); ++i) {
      const EngineOrderResonance& r = o.resonances[i];
      rows.push_back({static_cast<double>(i + 1), static_cast<double>(r.engine_order),
                      static_cast<double>(r.nodal_diameter), static_cast<double>(r.family), r.frequency_hz,
                      r.speed_rpm});
    }
    add(table_from_rows("engine_order_resonances",
                        {"row", "engine_order", "nodal_diameter", "family", "frequency_hz", "speed_rpm"}, rows));
  }
  if (o.campbell) {
    const CyclicCampbell& c = *o.campbell;
    std::vector<std::string> columns = {"row", "speed_rpm", "nodal_diameter"};
    const Eigen::Index campbell_families = c.frequencies_hz.empty() ? 0 : c.frequencies_hz.front().cols();
    for (Eigen::Index f = 0; f < campbell_families; ++f) columns.push_back(fmt::format("f{}_hz", f + 1));
    std::vector<std::vector<double>> rows;
    for (size_t d = 0; d < c.nodal_diameters.size(); ++d)
      for (size_t s = 0; s < c.speeds.size(); ++s) {
        std::vector<double> row = {static_cast<double>(rows.size() + 1), c.speeds[s] * 60.0 / (2 * std::numbers::pi),
                                   static_cast<double>(c.nodal_diameters[d])};
        for (Eigen::Index f = 0; f < campbell_families; ++f)
          row.push_back(c.frequencies_hz[d](static_cast<Eigen::Index>(s), f));
        rows.push_back(std::move(row));
      }
    add(table_from_rows("campbell", columns, rows));
    std::vector<std::vector<double>> x;
    for (size_t i = 0; i < o.crossings.size(); ++i) {
      const CyclicCrossing& r = o.crossings[i];
      x.push_back({static_cast<double>(i + 1), static_cast<double>(r.engine_order),
                   static_cast<double>(r.nodal_diameter), static_cast<double>(r.family),
                   r.speed * 60.0 / (2 * std::numbers::pi), r.frequency_hz});
    }
    if (!x.empty())
      add(table_from_rows("engine_order_crossings",
                          {"row", "engine_order", "nodal_diameter", "family", "speed_rpm", "frequency_hz"}, x));
  }
  return tables;
}

}  // namespace bb
