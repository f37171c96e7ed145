// What the subcommands of the command line share: the work-limit and fidelity options, the
// verdict line of a run, and the guard that turns exceptions into exit codes (common/errors.hpp).
#pragma once
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "common/work_limits.hpp"
#include "pipeline/run_case.hpp"

namespace bb::cli {

int failed_count(const RunRecord& r);
// The verdict of one run on stderr, user text through printable().
void print_outcome(const RunOutcome& o, const std::string& prefix);
// A subcommand's body: bad input -> exit 2, any other failure -> exit 3, the message on stderr.
int guarded(const std::function<int()>& body);

// A finite number of the case reader's range (common/input_number.hpp), > 0 or >= 0: the check of
// every numeric option that bounds work or scales data.
CLI::Validator input_number(bool positive);
// --max-work and --max-memory: the bounds every analysis's estimate is held to before it starts.
void add_limit_options(CLI::App* app, WorkLimits& limits);
// The same bounds as options of a child `bladebench run`.
void append_limit_args(const WorkLimits& limits, std::vector<std::string>& command);
// --fidelity on run and validate: the case's settings unless asked (see cases/README.md, "Fidelity").
void add_fidelity_option(CLI::App* app, FidelityMode& mode);

}  // namespace bb::cli
