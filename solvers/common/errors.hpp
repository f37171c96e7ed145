// Error kinds and the CLI exit codes they map to.
#pragma once
#include <stdexcept>
#include <string>

namespace bb {

enum ExitCode : int {
  exit_pass = 0,          // every check passed
  exit_check_failed = 1,  // the run completed, at least one check failed
  exit_bad_input = 2,     // a case, mesh or reference file is malformed or the model is ill-posed
  exit_solver_failed = 3  // a solver did not converge or broke down
};

// Malformed input. The message names the file, line and key where known.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The output folder cannot be used (a file where a folder should be, no permission, a folder that is
// not a report). Bad input too (exit 2): the user named the place.
class OutputError : public InputError {
 public:
  using InputError::InputError;
};

// A solver could not produce a trustworthy answer (no convergence, breakdown).
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bb
