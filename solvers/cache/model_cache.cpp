#include "cache/model_cache.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace bb {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kMagic = "bladebench-model-cache 1";

std::span<const std::byte> as_bytes(const std::vector<std::uint8_t>& v) {
  return {reinterpret_cast<const std::byte*>(v.data()), v.size()};
}

// Removes the least recently used entries until the folder's entries fit in `max_bytes`.
void prune(const fs::path& folder, std::uintmax_t max_bytes) {
  struct Entry {
    fs::path path;
    fs::file_time_type used;
    std::uintmax_t size;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    if (e.path().extension() != ".bbcache" || !e.is_regular_file(ec)) continue;
    entries.push_back({e.path(), e.last_write_time(ec), e.file_size(ec)});
    total += entries.back().size;
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= max_bytes) break;
    if (fs::remove(e.path, ec)) total -= e.size;
  }
}

}  // namespace

std::optional<fs::path> default_model_cache_folder() {
  if (const char* dir = std::getenv("BLADEBENCH_CACHE_DIR"); dir && *dir) return fs::path(dir);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "bladebench";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "bladebench";
  return std::nullopt;
}

CacheEntry::CacheEntry(const ModelCacheSettings& settings, const ContentKey& key) : settings_(settings) {
  if (program_fingerprint().empty()) {
    note_ = "the program's own file cannot be read, so no key could tell its versions apart: cache not used";
    return;
  }
  std::error_code ec;
  fs::create_directories(settings_.folder, ec);
  file_ = settings_.folder / (key.name() + ".bbcache");
  const fs::path lock = settings_.folder / (key.name() + ".lock");
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0 || ::flock(lock_fd_, LOCK_EX) != 0) {
    note_ = fmt::format("cannot lock {} ({}): cache not used", lock.string(), std::strerror(errno));
    if (lock_fd_ >= 0) ::close(lock_fd_);
    lock_fd_ = -1;
    return;
  }
  enabled_ = true;
}

CacheEntry::~CacheEntry() {
  if (lock_fd_ >= 0) {
    ::flock(lock_fd_, LOCK_UN);
    ::close(lock_fd_);
  }
}

std::optional<std::vector<std::uint8_t>> CacheEntry::load() {
  if (!enabled_) return std::nullopt;
  std::ifstream in(file_, std::ios::binary);
  if (!in) return std::nullopt;
  std::string header;
  std::getline(in, header);
  std::istringstream fields(header.size() > kMagic.size() ? header.substr(kMagic.size()) : std::string());
  std::uintmax_t size = 0;
  std::string checksum;
  const bool header_ok = header.starts_with(kMagic) && static_cast<bool>(fields >> size >> checksum);
  std::vector<std::uint8_t> payload;
  if (header_ok) {
    payload.resize(size);
    in.read(reinterpret_cast<char*>(payload.data()), static_cast<std::streamsize>(size));
    if (in.gcount() == static_cast<std::streamsize>(size) && in.peek() == std::char_traits<char>::eof() &&
        checksum_of(as_bytes(payload)) == checksum) {
      std::error_code ec;
      fs::last_write_time(file_, fs::file_time_type::clock::now(), ec);  // most recently used
      return payload;
    }
  }
  discard(header_ok ? "its size or checksum does not match its header" : "its header is not a cache header");
  return std::nullopt;
}

bool CacheEntry::store(const std::vector<std::uint8_t>& payload, double build_seconds) {
  if (!enabled_ || build_seconds < settings_.min_build_seconds) return false;
  const fs::path temp = file_.string() + fmt::format(".tmp-{}", ::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out << kMagic << ' ' << payload.size() << ' ' << checksum_of(as_bytes(payload)) << '\n';
    out.write(reinterpret_cast<const char*>(payload.data()), static_cast<std::streamsize>(payload.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(temp, ec);
      note_ = fmt::format("could not write {}: not cached", file_.string());
      return false;
    }
  }
  std::error_code ec;
  fs::rename(temp, file_, ec);
  if (ec) {
    fs::remove(temp, ec);
    note_ = fmt::format("could not write {}: not cached", file_.string());
    return false;
  }
  prune(file_.parent_path(), settings_.max_bytes);
  return true;
}

void CacheEntry::discard(const std::string& reason) {
  std::error_code ec;
  fs::remove(file_, ec);
  note_ = fmt::format("cache entry {} was damaged ({}): rebuilt", file_.filename().string(), reason);
}

}  // namespace bb
