// Independent jobs 0..n-1 on a few threads, the caller's among them: force levels, calibration starts.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace bb {

// Workers for n jobs when `threads` are asked (0 or less: one per core), never more than n.
inline std::size_t worker_count(std::size_t n, int threads) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  return std::min(n, threads > 0 ? static_cast<std::size_t>(threads) : cores);
}

// Calls work(i) once for every i in [0, n), on `workers` threads, in no set order. A job that
// throws stops none of the others; once all have ended, the exception of the lowest index is
// rethrown, where a serial run would have stopped.
template <class Work>
void for_each_index(std::size_t n, std::size_t workers, const Work& work) {
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  const auto drain = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        work(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t k = 1; k < workers; ++k) pool.emplace_back(drain);
    drain();
  }  // joined
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace bb
