#include "forced/level_relay.hpp"

#include <cstdio>
#include <exception>
#include <string>
#include <utility>

#include "common/errors.hpp"
#include "distributed/byte_record.hpp"
#include "distributed/distributed.hpp"

namespace bb {
namespace {

std::string to_bytes(const std::optional<LevelStart>& start) {
  distributed::ByteWriter w;
  w.put(static_cast<int>(start.has_value()));
  if (start) {
    w.put(std::vector<double>(start->x.data(), start->x.data() + start->x.size()));
    w.put(start->harmonics).put(start->force);
  }
  return w.bytes();
}

std::optional<LevelStart> start_from_bytes(const std::string& bytes) {
  distributed::ByteReader in(bytes);
  int has = 0;
  in.get(has);
  if (!has) return std::nullopt;
  std::vector<double> x;
  LevelStart s;
  in.get(x);
  in.get(s.harmonics);
  in.get(s.force);
  s.x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  return s;
}

int owner(std::size_t level) { return distributed::owner_of(level); }
int tag(std::size_t level) { return static_cast<int>(level); }

}  // namespace

bool LevelRelay::remote(std::size_t level) const {
  return scope_ == Scope::ranks && owner(level) != distributed::rank();
}

std::optional<LevelStart> LevelRelay::from_neighbour(std::size_t level) {
  if (level == 0 || level > published_.size()) return std::nullopt;
  if (remote(level - 1)) {
    // One thread per rank: nobody else fills this slot.
    if (!published_[level - 1]) {
      starts_[level - 1] = start_from_bytes(distributed::receive_from(owner(level - 1), tag(level - 1)));
      published_[level - 1] = true;
    }
    return starts_[level - 1];
  }
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
  if (level + 1 < published_.size() && remote(level + 1))
    distributed::send_to(owner(level + 1), tag(level), to_bytes(starts_[level]));
  changed_.notify_all();
}

void LevelRelay::finish() {
  if (scope_ != Scope::ranks) return;
  for (std::size_t level = 1; level < published_.size(); ++level)
    if (!remote(level) && remote(level - 1) && !published_[level - 1]) (void)from_neighbour(level);
  distributed::complete_sends();
}

LevelRelay::Guard::~Guard() {
  try {
    relay_.publish(level_, std::nullopt);
  } catch (const std::exception& e) {
    // The next level's rank would wait for ever: stop every rank instead.
    std::fprintf(stderr, "error: %s\n", e.what());
    distributed::abort_all(exit_solver_failed);
  }
}

}  // namespace bb
