// Accuracy vs cost of solid modal models: element type x mesh refinement, first frequencies
// against the finest hex20 mesh of the study (the best converged answer it has).
#pragma once
#include <string>
#include <vector>

#include "analysis/modal_spec.hpp"
#include "cache/model_cache_settings.hpp"
#include "model/model_spec.hpp"
#include "study/study_progress.hpp"
#include "study/study_spec.hpp"

namespace bb {

struct ModalRefinementRow {
  ElementType element = ElementType::hex20;
  int refinement = 1;
  int n_free_dofs = 0;
  std::vector<double> frequencies_hz;  // the first `modes`
  double max_error = 0.0;              // max_k |f_k / f_ref_k - 1|
  double rms_error = 0.0;
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;
};

struct ModalRefinementResult {
  std::vector<ModalRefinementRow> rows;
  int reference_row = -1;  // the finest hex20 row (else the last row)
  int modes = 0;
};

ModalRefinementResult run_modal_refinement_study(const ModelSpec& spec, const ModalSpec& modal,
                                                 const ModalRefinementStudySpec& study,
                                                 const StudyProgress& progress = {},
                                                 const ModelCacheSettings* cache = nullptr);

}  // namespace bb
