#include "cli/command_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "common/errors.hpp"
#include "common/input_number.hpp"
#include "common/user_text.hpp"

namespace bb::cli {

int failed_count(const bb::RunRecord& r) {
  return static_cast<int>(
      std::count_if(r.checks.begin(), r.checks.end(), [](const bb::CheckEntry& e) { return !e.pass; }));
}

void print_outcome(const bb::RunOutcome& o, const std::string& prefix) {
  const bb::RunRecord& r = o.record;
  const std::string report = o.written ? (o.out_dir / "report.md").string() : std::string("no report written");
  std::fprintf(stderr, "%s%s: %s (%zu checks, %d failed, %.3f s) -> %s\n", prefix.c_str(),
               bb::printable(r.case_name).c_str(), bb::status_name(r.status).c_str(), r.checks.size(), failed_count(r),
               r.wall_seconds, bb::printable(report).c_str());
  if (!r.message.empty()) std::fprintf(stderr, "  error: %s\n", bb::printable(r.message).c_str());
  for (const std::string& w : r.warnings) std::fprintf(stderr, "  warning: %s\n", bb::printable(w).c_str());
  for (const bb::CheckEntry& e : r.checks)
    if (!e.pass)
      std::fprintf(stderr, "  FAIL %s: computed %.9g, expected %s reference %.9g (tolerance %.3g, |error| %.3g)\n",
                   bb::printable(e.name).c_str(), e.computed, bb::relation_symbol(e.relation), e.reference, e.tolerance,
                   e.abs_error);
}

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const bb::InputError& e) {
    std::fprintf(stderr, "error: %s\n", bb::printable(e.what()).c_str());
    return bb::exit_bad_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", bb::printable(e.what()).c_str());
    return bb::exit_solver_failed;
  }
}


CLI::Validator input_number(bool positive) {
  // CLI::PositiveNumber lets nan through (nan <= 0 is false), which would switch a bound off.
  return CLI::Validator(
      [positive](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v)) return fmt::format("'{}' is not a number", text);
        if (std::string problem = bb::number_problem(v); !problem.empty()) return problem;
        if (positive ? !(v > 0.0) : !(v >= 0.0)) return fmt::format("{} must be {}", text, positive ? "> 0" : ">= 0");
        return {};
      },
      positive ? "POSITIVE" : "NONNEGATIVE");
}

void add_limit_options(CLI::App* app, bb::WorkLimits& limits) {
  app->add_option("--max-work", limits.operations,
                  "Largest estimated floating-point operations of one analysis (default 1e12); a larger input is "
                  "refused before it runs")
      ->check(input_number(true));
  app->add_option_function<double>(
         "--max-memory", [&limits](double gb) { limits.bytes = gb * 1e9; },
         "Largest estimated memory of one analysis [GB] (default: three quarters of this machine's)")
      ->check(input_number(true));
}

void append_limit_args(const bb::WorkLimits& limits, std::vector<std::string>& command) {
  command.insert(command.end(), {"--max-work", fmt::format("{:.17g}", limits.operations)});
  if (limits.bytes > 0) command.insert(command.end(), {"--max-memory", fmt::format("{:.17g}", limits.bytes / 1e9)});
}

void add_fidelity_option(CLI::App* app, bb::FidelityMode& mode) {
  static const std::map<std::string, bb::FidelityMode> modes = [] {
    std::map<std::string, bb::FidelityMode> m;
    for (bb::FidelityMode each : bb::kFidelityModes) m.emplace(bb::fidelity_mode_name(each), each);
    return m;
  }();
  app->add_option("--fidelity", mode,
                  "fixed: the case's own settings (default); fast / reference: the cheapest / finest level of every "
                  "[fidelity] axis; auto: the cheapest levels whose estimated error meets the [fidelity] target")
      ->transform(CLI::CheckedTransformer(modes, CLI::ignore_case));
}

}  // namespace bb::cli
