#include "study/modal_refinement.hpp"

#include <cmath>

#include "analysis/modal_analysis.hpp"
#include "model/build_model.hpp"

namespace bb {

ModalRefinementResult run_modal_refinement_study(const ModelSpec& spec, const ModalSpec& modal_spec,
                                                 const ModalRefinementStudySpec& s, const StudyProgress& progress,
                                                 const ModelCacheSettings* cache) {
  ModalRefinementResult out;
  out.modes = s.modes;
  const int total = static_cast<int>(s.elements.size() * s.refinements.size());
  if (progress) progress(0, total);
  for (ElementType element : s.elements) {
    for (int r : s.refinements) {
      ModelSpec level = spec;
      level.mesh.element = element;
      if (level.mesh.kind == MeshSpec::Kind::two_blade) {
        level.mesh.two_blade.refinement = r;
        level.mesh.two_blade.thickness_divisions = 0;  // 4 r, as the article's default
      } else {
        for (HexBlockSpec& b : level.mesh.blocks) {
          b.element = element;
          b.nx *= r;
          b.ny *= r;
          b.nz *= r;
        }
      }
      const Model model = build_model(level);
      ModeSelection lowest;
      lowest.lowest = s.modes;
      const ModalResult modal = solve_modal(model, lowest, modal_spec.options, cache);
      ModalRefinementRow row;
      row.element = element;
      row.refinement = r;
      row.n_free_dofs = modal.n_free_dofs;
      row.frequencies_hz.assign(modal.frequencies_hz.data(), modal.frequencies_hz.data() + modal.frequencies_hz.size());
      row.assembly_seconds = modal.assembly_seconds;
      row.solve_seconds = modal.solve_seconds;
      out.rows.push_back(std::move(row));
      if (progress) progress(static_cast<int>(out.rows.size()), total);
    }
  }
  for (size_t i = 0; i < out.rows.size(); ++i)
    if (out.rows[i].element == ElementType::hex20 &&
        (out.reference_row < 0 ||
         out.rows[i].n_free_dofs > out.rows[static_cast<size_t>(out.reference_row)].n_free_dofs))
      out.reference_row = static_cast<int>(i);
  if (out.reference_row < 0) out.reference_row = static_cast<int>(out.rows.size()) - 1;
  const auto& ref = out.rows[static_cast<size_t>(out.reference_row)].frequencies_hz;
  for (ModalRefinementRow& row : out.rows) {
    double sum = 0.0;
    for (size_t k = 0; k < ref.size() && k < row.frequencies_hz.size(); ++k) {
      const double e = std::abs(row.frequencies_hz[k] / ref[k] - 1.0);
      row.max_error = std::max(row.max_error, e);
      sum += e * e;
    }
    row.rms_error = std::sqrt(sum / static_cast<double>(ref.size()));
  }
  return out;
}

}  // namespace bb
