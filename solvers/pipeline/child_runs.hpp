// Several bladebench runs at once, each in its own process (validate -j): a crash, a stray global or
// a library that is not thread-safe stays inside its run, and each run's report is written as by
// `bladebench run`.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace bb {

struct ChildResult {
  int exit_code = -1;  // the process's exit code, or -1 when it did not exit normally
  int signal = 0;      // the signal that ended it, 0 when it exited
  std::string output;  // what it wrote to stdout and stderr, interleaved as written
};

// Runs `commands` (argv vectors; argv[0] a path) with at most `jobs` alive at a time, started in
// order; `done(i, result)` is called in the order they finish. Throws std::runtime_error when a
// process cannot be started.
void run_children(const std::vector<std::vector<std::string>>& commands, int jobs,
                  const std::function<void(size_t, const ChildResult&)>& done);

}  // namespace bb
