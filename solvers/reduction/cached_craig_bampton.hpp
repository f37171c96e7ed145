// craig_bampton() through the model cache (cache/model_cache.hpp): the key is the stiffness and
// mass matrices, the masters and their names, the options and the program itself, so the two-blade
// reduction shared by Tables VIII, IX, XI and the time-domain cases is computed once.
#pragma once
#include "cache/model_cache_settings.hpp"
#include "reduction/craig_bampton.hpp"

namespace bb {

// Same contract as craig_bampton(). `timing` also says whether the model came from the cache;
// without `cache`, craig_bampton() runs.
ReducedModel cached_craig_bampton(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                  const std::vector<int>& masters, const std::vector<ReducedDof>& master_names,
                                  const CraigBamptonOptions& options, const ModelCacheSettings* cache,
                                  CraigBamptonTiming* timing = nullptr);

}  // namespace bb
