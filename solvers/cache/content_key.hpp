// Content keys of the model cache: a 128-bit hash (XXH3) of everything a derived model is computed
// from - the matrices themselves, not the case text that led to them - and of the program that
// computes it, so an entry can only be found by the same inputs through the same code.
#pragma once
#include <Eigen/Sparse>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace bb {

class ContentKey {
 public:
  // `kind` names what is keyed ("craig_bampton"); it prefixes the entry's file name.
  explicit ContentKey(std::string_view kind);
  ~ContentKey();
  ContentKey(const ContentKey&) = delete;
  ContentKey& operator=(const ContentKey&) = delete;

  ContentKey& add(std::span<const std::byte> bytes);
  ContentKey& add(std::string_view text);  // length-prefixed: ("ab","c") != ("a","bc")
  ContentKey& add(std::int64_t value);
  ContentKey& add(double value);
  // Shape, pattern and values (compressed column storage).
  ContentKey& add(const Eigen::SparseMatrix<double>& matrix);

  const std::string& kind() const { return kind_; }
  // "<kind>-<32 hex digits>"
  std::string name() const;

 private:
  std::string kind_;
  void* state_;  // XXH3_state_t, kept out of the header
};

// XXH3-128 of this program's executable file (/proc/self/exe), computed once; empty when it cannot
// be read (the cache is then not used: a key without it could outlive a change of the code).
const std::string& program_fingerprint();

// XXH3-64 of `bytes` as 16 hex digits: the checksum of an entry's payload.
std::string checksum_of(std::span<const std::byte> bytes);

}  // namespace bb
