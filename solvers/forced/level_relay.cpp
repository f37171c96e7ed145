#include "forced/level_relay.hpp"

#include <utility>

namespace bb {

std::optional<LevelStart> LevelRelay::from_neighbour(std::size_t level) const {
  if (level == 0 || level > published_.size()) return std::nullopt;
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return static_cast<bool>(published_[level - 1]); });
  return starts_[level - 1];
}

void LevelRelay::publish(std::size_t level, std::optional<LevelStart> start) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (level >= published_.size() || published_[level]) return;
    published_[level] = true;
    starts_[level] = std::move(start);
  }
  changed_.notify_all();
}

}  // namespace bb
