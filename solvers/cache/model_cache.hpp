// The model cache: derived models that cost tens of seconds to compute (Craig-Bampton reductions of
// the two-blade mesh) stored on disk under a content key, so the cases that share one compute it
// once. Used only where a caller hands its settings in (the CLI does, `--no-cache` to bypass;
// cases/README.md).
//
// An entry is one file `<key name>.bbcache`: a header line with the payload's size and checksum,
// then the payload. An entry whose size or checksum disagrees, or that does not decode, is
// reported, removed and rebuilt. A lock file per entry makes a second process that wants the same
// entry wait for the first to store it instead of computing it too.
#pragma once
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "cache/cache_use.hpp"
#include "cache/content_key.hpp"
#include "cache/model_cache_settings.hpp"
#include "common/seconds_since.hpp"

namespace bb {

// One entry of the cache in `settings`, locked for as long as the object lives.
class CacheEntry {
 public:
  CacheEntry(const ModelCacheSettings& settings, const ContentKey& key);
  ~CacheEntry();
  CacheEntry(const CacheEntry&) = delete;
  CacheEntry& operator=(const CacheEntry&) = delete;

  bool enabled() const { return enabled_; }
  // The stored payload when the entry exists and is sound; otherwise nullopt, and a damaged entry
  // is removed with the reason in note().
  std::optional<std::vector<std::uint8_t>> load();
  // Writes the entry (temporary file, then rename) and prunes the folder to its size bound; returns
  // false, writing nothing, when `build_seconds` is below the settings' minimum. A failure to write
  // leaves the cache as it was and says why in note(); it never fails the run.
  bool store(const std::vector<std::uint8_t>& payload, double build_seconds);
  // Call when the payload did not decode: the entry is removed.
  void discard(const std::string& reason);

  const std::filesystem::path& file() const { return file_; }
  const std::string& note() const { return note_; }

 private:
  ModelCacheSettings settings_;
  bool enabled_ = false;
  std::filesystem::path file_;
  int lock_fd_ = -1;
  std::string note_;
};

namespace detail {
template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
}  // namespace detail

// The protocol every kind of entry follows. Without a cache (`cache` null), `build()` runs, timed. Otherwise
// the entry keyed by `kind`, the program and what `fill_key(ContentKey&)` adds is locked and looked
// up: `decode(json)` turns a sound entry back into the result (and throws on one that does not
// fit the model, which is then discarded and rebuilt); a `decode` that returns std::optional may
// answer nullopt for a sound entry that does not cover this request (fewer modes than asked), which
// is then rebuilt and replaced. Failing that, `build()` runs, timed, and `encode(result)` (json) is
// stored with its build time when that was long enough. `use` says what happened;
// `use.build_seconds` is the build time, here or in the run that stored the entry.
template <class Result, class FillKey, class Build, class Encode, class Decode>
Result through_model_cache(const ModelCacheSettings* cache, std::string_view kind, FillKey fill_key, Build build,
                           Encode encode, Decode decode, CacheUse& use) {
  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  if (!cache) {
    Result result = build();
    use.outcome = CacheUse::Outcome::off;
    use.build_seconds = seconds_since(t0);
    return result;
  }
  ContentKey key(kind);
  key.add(program_fingerprint());
  fill_key(key);
  CacheEntry entry(*cache, key);
  t0 = Clock::now();
  if (const auto payload = entry.load()) {
    try {
      const nlohmann::json j = nlohmann::json::from_cbor(*payload);
      std::optional<Result> result;
      if constexpr (detail::IsOptional<decltype(decode(j.at("result")))>::value)
        result = decode(j.at("result"));
      else
        result.emplace(decode(j.at("result")));
      if (result) {
        use.outcome = CacheUse::Outcome::loaded;
        use.build_seconds = j.at("build_seconds").template get<double>();
        use.seconds = seconds_since(t0);
        return std::move(*result);
      }
    } catch (const std::exception& e) {
      entry.discard(e.what());
    }
  }
  t0 = Clock::now();
  Result result = build();
  use.build_seconds = seconds_since(t0);
  t0 = Clock::now();
  const nlohmann::json j = {{"build_seconds", use.build_seconds}, {"result", encode(result)}};
  const bool stored = entry.store(nlohmann::json::to_cbor(j), use.build_seconds);
  use.seconds = seconds_since(t0);
  use.outcome = stored ? CacheUse::Outcome::stored : CacheUse::Outcome::not_stored;
  use.note = entry.note();
  return result;
}

}  // namespace bb
