// What a model-cache lookup did (cache/model_cache.hpp), for the report: its own header so that the
// results that carry it (a Craig-Bampton reduction, a set of modes) do not pull the cache's
// serialization (nlohmann/json) into every file that includes them.
#pragma once
#include <string>

namespace bb {

struct CacheUse {
  enum class Outcome { off, loaded, stored, not_stored };
  Outcome outcome = Outcome::off;
  double seconds = 0.0;        // to load or to store the entry
  double build_seconds = 0.0;  // to compute it, here or in the run that stored it
  std::string note;            // why the cache was not used, or an entry was rebuilt or not written
};

}  // namespace bb
