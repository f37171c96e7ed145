#include "analysis/modal_analysis.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "linalg/cached_modes.hpp"
#include "linalg/inertia.hpp"
#include "linalg/slepc_modes.hpp"

namespace bb {

ModalResult solve_modal(const Model& model, const ModeSelection& selection, const ModalOptions& options,
                        const ModelCacheSettings* cache) {
  return solve_modal(model, assemble_free_system(model), selection, options, cache);
}

ModalResult solve_modal(const Model& model, const FreeSystem& system, const ModeSelection& selection,
                        const ModalOptions& base_options, const ModelCacheSettings* cache) {
  const Mesh& mesh = model.mesh;
  const DofMap& dofs = system.dofs;
  ModalOptions options = base_options;
  options.n_modes = selection.lowest;
  options.ordering = ordering_for_dimension(mesh.dim);
  if (options.n_modes >= dofs.n_free)
    throw InputError(fmt::format("'analysis.modes': asked for {} modes of a model with only {} free DOFs",
                                 options.n_modes, dofs.n_free));
  ModalResult result;
  result.n_free_dofs = dofs.n_free;
  const auto t1 = std::chrono::steady_clock::now();
  result.assembly_seconds = system.assembly_seconds;
  // A band is sized by the Sturm count at its top: exactly the modes below f_max are asked for.
  const double two_pi = 2 * std::numbers::pi;
  const std::optional<double> band_top =
      selection.band_max_hz ? std::optional<double>(std::pow(two_pi * *selection.band_max_hz, 2)) : std::nullopt;
  const auto refuse_band_of_every_mode = [&](Eigen::Index below_top) {
    if (below_top >= dofs.n_free)
      throw InputError(
          fmt::format("'analysis.band_hz': the band holds all {} modes of the model; lower its top", dofs.n_free));
  };
  const bool sliced_band = band_top && options.eigensolver == Eigensolver::slepc;
  if (band_top && !sliced_band) {
    const InertiaCount below = eigenvalues_below(system.stiffness, system.mass, *band_top);
    if (!below.ok)
      throw SolverError(fmt::format("modal band: Sturm count at {} Hz: {}", *selection.band_max_hz, below.message));
    refuse_band_of_every_mode(below.negative);
    options.n_modes = std::max(below.negative, 1);
  }
  // SLEPc slices the band itself: its count comes from the factorizations at the band's ends.
  ModalSolution sol = sliced_band ? slepc_modes_below(system.stiffness, system.mass, *band_top, options)
                                  : cached_lowest_modes(system.stiffness, system.mass, options, cache, &result.cache);
  if (sliced_band) refuse_band_of_every_mode(sol.eigenvalues.size());
  if (selection.band_min_hz || selection.band_max_hz) {
    std::vector<Eigen::Index> keep;
    for (Eigen::Index i = 0; i < sol.eigenvalues.size(); ++i) {
      const double f = std::sqrt(std::max(sol.eigenvalues[i], 0.0)) / two_pi;
      if (f >= selection.band_min_hz.value_or(0.0) && f <= selection.band_max_hz.value_or(INFINITY)) keep.push_back(i);
    }
    ModalSolution band = sol;
    band.eigenvalues.resize(static_cast<Eigen::Index>(keep.size()));
    band.shapes.resize(sol.shapes.rows(), static_cast<Eigen::Index>(keep.size()));
    for (size_t j = 0; j < keep.size(); ++j) {
      band.eigenvalues[static_cast<Eigen::Index>(j)] = sol.eigenvalues[keep[j]];
      band.shapes.col(static_cast<Eigen::Index>(j)) = sol.shapes.col(keep[j]);
    }
    sol = std::move(band);
  }
  result.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  if (result.cache.outcome == CacheUse::Outcome::loaded)
    result.solve_seconds += result.cache.build_seconds - result.cache.seconds;
  result.iterations = sol.iterations;
  result.lanczos_runs = sol.lanczos_runs;
  result.sturm_count = sol.sturm_count;
  result.sturm_frequency_hz = std::sqrt(std::max(sol.sturm_shift, 0.0)) / two_pi;
  result.sturm_seconds = sol.sturm_seconds;
  for (Eigen::Index k = 0; k < sol.eigenvalues.size(); ++k)
    result.rigid_body_modes += sol.eigenvalues[k] < 1e-8 * sol.eigenvalues.maxCoeff() ? 1 : 0;
  result.max_residual = sol.max_residual;
  result.frequencies_hz = sol.eigenvalues.array().max(0.0).sqrt() / (2 * std::numbers::pi);
  result.effective_mass_fraction.resize(sol.shapes.cols(), mesh.dim);
  for (int d = 0; d < mesh.dim; ++d) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.n_free);
    for (int i = 0; i < dofs.n_free; ++i) r[i] = dofs.free_dofs[i] % mesh.dim == d ? 1.0 : 0.0;
    const Eigen::VectorXd mr = system.mass * r;
    const double total = r.dot(mr);
    for (Eigen::Index k_mode = 0; k_mode < sol.shapes.cols(); ++k_mode) {
      const double gamma = sol.shapes.col(k_mode).dot(mr);
      result.effective_mass_fraction(k_mode, d) = total > 0 ? gamma * gamma / total : 0.0;
    }
  }
  for (Eigen::Index k_mode = 0; k_mode < sol.shapes.cols(); ++k_mode) {
    result.shapes.push_back(nodal_rows(dofs, sol.shapes.col(k_mode)));
  }
  return result;
}

ModalResult solve_modal(const Model& model, const ModalOptions& options) {
  ModeSelection lowest;
  lowest.lowest = options.n_modes;
  return solve_modal(model, lowest, options);
}

ResultTable frequency_table(const Eigen::VectorXd& frequencies_hz) {
  ResultTable t;
  t.name = "frequencies";
  t.columns = {"mode", "frequency_hz"};
  t.values.resize(frequencies_hz.size(), 2);
  for (Eigen::Index i = 0; i < frequencies_hz.size(); ++i) {
    t.values(i, 0) = static_cast<double>(i + 1);
    t.values(i, 1) = frequencies_hz[i];
  }
  return t;
}

ResultTable participation_table(const ModalResult& result) {
  ResultTable t;
  t.name = "modal_participation";
  t.columns = {"mode", "frequency_hz", "eff_mass_x", "eff_mass_y"};
  if (result.effective_mass_fraction.cols() == 3) t.columns.push_back("eff_mass_z");
  t.values.resize(result.frequencies_hz.size(), static_cast<Eigen::Index>(t.columns.size()));
  for (Eigen::Index i = 0; i < result.frequencies_hz.size(); ++i) {
    t.values(i, 0) = static_cast<double>(i + 1);
    t.values(i, 1) = result.frequencies_hz[i];
    t.values.row(i).tail(result.effective_mass_fraction.cols()) = result.effective_mass_fraction.row(i);
  }
  return t;
}

}  // namespace bb
