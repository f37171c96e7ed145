// `bladebench compare-models CASE CASE...`: calibrate several model forms on the same data and rank
// them by what they predict of the held-out curves and by AIC/BIC (identify/model_comparison.hpp).
// Exit 0 when every fit converged, 3 when one did not, 2 for bad input (cases on other data).
#pragma once
#include <string>
#include <vector>

#include "cache/model_cache_settings.hpp"
#include "common/work_limits.hpp"

namespace bb::cli {

struct CompareModelsArgs {
  std::vector<std::string> cases;
  std::string out = "reports/model-comparison";
  bool no_plots = false;
  bool leave_one_out = false;  // refit each model once per fitted curve, that curve held out
  WorkLimits limits;
  const ModelCacheSettings* cache = nullptr;
};

int compare_models_command(const CompareModelsArgs& a);

}  // namespace bb::cli
