#include "linalg/blas_threads.hpp"

#include <dlfcn.h>

#include <mutex>

namespace bb {
namespace {

template <class Function>
Function lookup(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

void use_one_thread_per_factorization() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (const auto set_threads = lookup<void (*)(int)>("openblas_set_num_threads")) set_threads(1);
    if (const auto set_levels = lookup<void (*)(int)>("omp_set_max_active_levels")) set_levels(0);
  });
}

bool blas_allows_concurrent_calls() {
  constexpr int kSequentialBuild = 0;  // openblas_get_parallel(): 0 none, 1 pthreads, 2 OpenMP
  const auto parallel = lookup<int (*)()>("openblas_get_parallel");
  return !parallel || parallel() != kSequentialBuild;
}

}  // namespace bb
