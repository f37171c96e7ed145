// lowest_modes() through the model cache (cache/model_cache.hpp): the modes of the two-blade mesh,
// solved for Table VI (20) and for Tables VIII-IX's full model (24), are computed once. The key is
// K, M, every modal option but the number of modes, and the program itself: an entry holding more
// modes serves a request for fewer; one holding fewer is replaced by the larger solution.
#pragma once
#include "cache/cache_use.hpp"
#include "cache/model_cache_settings.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {

// `use->build_seconds` is the time of lowest_modes, here or in the run that stored the entry.
// Without `cache`, lowest_modes() runs.
ModalSolution cached_lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                  const ModalOptions& options, const ModelCacheSettings* cache,
                                  CacheUse* use = nullptr);

}  // namespace bb
