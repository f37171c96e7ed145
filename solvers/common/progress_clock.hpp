// How far a long loop has come and about how long it has left, for progress lines on a terminal:
// the time per item so far, times the items left. Items are the loop's own units (force levels,
// grid points), so the estimate is as coarse as they are uneven.
#pragma once
#include <fmt/format.h>

#include <chrono>
#include <mutex>
#include <string>

namespace bb {

class ProgressClock {
 public:
  explicit ProgressClock(int total) : total_(total), start_(std::chrono::steady_clock::now()) {}

  void finished(int items) { done_ = items; }

  // "3 of 15 done, about 40 s left"; "1 of 15 running" before any is done.
  std::string status() const {
    if (done_ <= 0 || total_ <= 0) return fmt::format("1 of {} running", total_);
    return done_ >= total_ ? fmt::format("{} of {} done", done_, total_)
                           : fmt::format("{} of {} done, about {} left", done_, total_, time_left());
  }

  // For loops that may stop early (an optimizer's iterations against its cap): "at most 3 min
  // left", the time per item so far times the items the cap still allows; empty before any item.
  std::string bound() const {
    if (done_ <= 0 || total_ <= 0 || done_ >= total_) return {};
    return fmt::format("at most {} left", time_left());
  }

 private:
  std::string time_left() const {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = elapsed / done_ * (total_ - done_);
    return left >= 120 ? fmt::format("{:.0f} min", left / 60) : fmt::format("{:.0f} s", left);
  }

  int total_ = 0, done_ = 0;
  std::chrono::steady_clock::time_point start_;
};

// The lines of `progress` with the clock's status appended (empty when `progress` is).
template <typename Progress>
Progress with_clock(const Progress& progress, const ProgressClock& clock) {
  if (!progress) return {};
  return [&progress, &clock](const std::string& line) { progress(line + "  [" + clock.status() + "]"); };
}

// As with_clock, for workers that report at once: one line at a time under `lock`, which the
// caller also holds to advance the clock.
template <typename Progress>
Progress with_clock_locked(const Progress& progress, const ProgressClock& clock, std::mutex& lock) {
  if (!progress) return {};
  return [&progress, &clock, &lock](const std::string& line) {
    const std::lock_guard<std::mutex> guard(lock);
    progress(line + "  [" + clock.status() + "]");
  };
}

}  // namespace bb
