// lowest_modes() through the model cache (cache/model_cache.hpp): the modes of the two-blade mesh,
// solved for Table VI and again for Table IX's full model, are computed once. The key is K, M,
// every modal option and the program itself.
#pragma once
#include "cache/model_cache.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {

// `use->build_seconds` is the time of lowest_modes, here or in the run that stored the entry.
ModalSolution cached_lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                  const ModalOptions& options, CacheUse* use = nullptr);

}  // namespace bb
