// Where the model cache keeps its entries and how much it may hold. A solve that may use the cache
// is handed these (`const ModelCacheSettings*`); null, the default, computes everything and stores
// nothing. Its own header so that the analyses can take it without the cache's serialization.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>

namespace bb {

struct ModelCacheSettings {
  std::filesystem::path folder;
  std::uintmax_t max_bytes = std::uintmax_t{4} << 30;  // least recently used entries go beyond this
  double min_build_seconds = 1.0;                      // cheaper results are not worth an entry (and its disk space)
};

// The settings to hand a solve: null when there are none (no cache).
inline const ModelCacheSettings* cache_or_none(const std::optional<ModelCacheSettings>& settings) {
  return settings ? &*settings : nullptr;
}

// The folder the CLI uses unless told otherwise: $BLADEBENCH_CACHE_DIR, else
// $XDG_CACHE_HOME/bladebench, else $HOME/.cache/bladebench; nullopt when none is set.
std::optional<std::filesystem::path> default_model_cache_folder();

}  // namespace bb
