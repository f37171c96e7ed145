#include "cache/content_key.hpp"

#include <fmt/format.h>
#include <xxhash.h>

#include <fstream>
#include <iterator>
#include <vector>

namespace bb {
namespace {

XXH3_state_t* state(void* p) { return static_cast<XXH3_state_t*>(p); }

std::string hex128(XXH128_hash_t h) { return fmt::format("{:016x}{:016x}", h.high64, h.low64); }

template <class T>
std::span<const std::byte> bytes_of(const T* data, size_t count) {
  return {reinterpret_cast<const std::byte*>(data), count * sizeof(T)};
}

}  // namespace

ContentKey::ContentKey(std::string_view kind) : kind_(kind), state_(XXH3_createState()) {
  if (!state_) throw std::bad_alloc();
  XXH3_128bits_reset(state(state_));
  add(kind);
}

ContentKey::~ContentKey() { XXH3_freeState(state(state_)); }

ContentKey& ContentKey::add(std::span<const std::byte> bytes) {
  XXH3_128bits_update(state(state_), bytes.data(), bytes.size());
  return *this;
}

ContentKey& ContentKey::add(std::string_view text) {
  add(static_cast<std::int64_t>(text.size()));
  return add(bytes_of(text.data(), text.size()));
}

ContentKey& ContentKey::add(std::int64_t value) { return add(bytes_of(&value, 1)); }

ContentKey& ContentKey::add(double value) { return add(bytes_of(&value, 1)); }

ContentKey& ContentKey::add(const Eigen::SparseMatrix<double>& matrix) {
  if (!matrix.isCompressed()) {
    Eigen::SparseMatrix<double> compressed = matrix;
    compressed.makeCompressed();
    return add(compressed);
  }
  const Eigen::SparseMatrix<double>& compressed = matrix;
  add(static_cast<std::int64_t>(compressed.rows()));
  add(static_cast<std::int64_t>(compressed.cols()));
  add(static_cast<std::int64_t>(compressed.nonZeros()));
  add(bytes_of(compressed.outerIndexPtr(), static_cast<size_t>(compressed.outerSize()) + 1));
  add(bytes_of(compressed.innerIndexPtr(), static_cast<size_t>(compressed.nonZeros())));
  return add(bytes_of(compressed.valuePtr(), static_cast<size_t>(compressed.nonZeros())));
}

std::string ContentKey::name() const { return kind_ + "-" + hex128(XXH3_128bits_digest(state(state_))); }

const std::string& program_fingerprint() {
  static const std::string fingerprint = [] {
    std::ifstream in("/proc/self/exe", std::ios::binary);
    if (!in) return std::string();
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) return std::string();
    return hex128(XXH3_128bits(bytes.data(), bytes.size()));
  }();
  return fingerprint;
}

std::string checksum_of(std::span<const std::byte> bytes) {
  return fmt::format("{:016x}", XXH3_64bits(bytes.data(), bytes.size()));
}

}  // namespace bb
