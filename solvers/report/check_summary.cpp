#include "report/check_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "report/number_format.hpp"

namespace bb {
namespace {

// Misses named in the verdict; the rest are counted (all are in the checks table).
constexpr size_t kMissesShown = 8;

bool relative_only(const CheckEntry& e, const CheckSpec* spec) {
  return spec && spec->rel_tol > 0.0 && spec->abs_tol == 0.0 && e.reference != 0.0 && std::isfinite(e.reference);
}

// The entry's name without its check's name in front ("ip_hz level 9").
// How the check pairs computed rows with reference rows, for its summary line ("" by key).
std::string pairing(const CheckSpec& spec) {
  switch (spec.match) {
    case CheckSpec::Match::key:
      return "";
    case CheckSpec::Match::mac:
      return fmt::format(", modes paired by shape (MAC >= {})", spec.min_mac);
    case CheckSpec::Match::label:
      return fmt::format(", rows paired by label ({})", fmt::join(spec.labels, ", "));
  }
  return "";
}

std::string entry_label(const CheckEntry& e) {
  const std::string prefix = e.group + ": ";
  return e.name.starts_with(prefix) ? e.name.substr(prefix.size()) : e.name;
}

// A magnitude as a percentage, without the sign format_percent gives it.
std::string unsigned_percent(double fraction) {
  const std::string p = format_percent(std::abs(fraction));
  return p.front() == '+' ? p.substr(1) : p;
}

int check_count(const RunRecord& run) {
  std::set<std::string> groups;
  for (const CheckEntry& e : run.checks) groups.insert(e.group);
  return static_cast<int>(groups.size());
}

std::string status_headline(RunStatus status) {
  switch (status) {
    case RunStatus::pass:
      return "**PASS**";
    case RunStatus::fail:
      return "**FAIL**";
    case RunStatus::no_checks:
      return "**NO CHECKS**";
    case RunStatus::bad_input:
      return "**BAD INPUT** (exit 2)";
    case RunStatus::solver_failed:
      return "**SOLVER FAILED** (exit 3)";
  }
  return "?";
}

}  // namespace

std::string table_cell(const std::string& text) {
  std::string out;
  for (char c : text)
    out += c == '|' ? std::string("\\|") : c == '\n' || c == '\r' ? std::string(" ") : std::string(1, c);
  return out;
}

const CheckSpec* spec_of(const RunRecord& run, const std::string& group) {
  for (const CheckSpec& spec : run.check_specs)
    if (spec.name == group) return &spec;
  return nullptr;
}

const CheckSpec* spec_of(const RunRecord& run, const CheckEntry& e) { return spec_of(run, e.group); }

std::string entry_error(const CheckEntry& e, const CheckSpec* spec) {
  const double difference = e.computed - e.reference;
  if (!std::isfinite(difference)) return format_number(difference);
  if (relative_only(e, spec)) return format_percent(difference / std::abs(e.reference));
  return fmt::format("{}{}", difference > 0.0 ? "+" : "", format_quantity(difference, unit_of_column(e.column)));
}

std::string entry_tolerance(const CheckEntry& e, const CheckSpec* spec) {
  if (relative_only(e, spec)) return unsigned_percent(spec->rel_tol);
  if (spec && spec->rel_tol > 0.0 && spec->abs_tol > 0.0)
    return format_quantity(spec->abs_tol, unit_of_column(e.column)) + " + " + unsigned_percent(spec->rel_tol);
  return format_quantity(e.tolerance, unit_of_column(e.column));
}

void write_verdict(std::ostream& out, const RunRecord& run) {
  const std::string timing = fmt::format("Run time {}; fidelity: {}.", format_seconds(run.wall_seconds),
                                         run.fidelity.empty() ? std::string("the case's settings") : run.fidelity);
  std::vector<const CheckEntry*> misses;
  const CheckEntry* closest = nullptr;
  for (const CheckEntry& e : run.checks) {
    if (!e.pass) misses.push_back(&e);
    if (!closest || tolerance_used(e) > tolerance_used(*closest)) closest = &e;
  }
  std::stable_sort(misses.begin(), misses.end(),
                   [](const CheckEntry* a, const CheckEntry* b) { return tolerance_used(*a) > tolerance_used(*b); });
  const size_t n = run.checks.size();
  const int checks = check_count(run);
  out << status_headline(run.status) << ": ";
  if (run.status == RunStatus::bad_input || run.status == RunStatus::solver_failed) {
    out << (run.message.empty() ? std::string("no verdict") : "no verdict, see the message below") << ". " << timing
        << "\n\n";
  } else if (n == 0) {
    out << "the case has no checks. " << timing << "\n\n";
  } else if (misses.empty()) {
    out << fmt::format(
        "all {} check entries within their tolerance ({} check{}; the closest uses {} of its "
        "tolerance: {}, {}). {}\n\n",
        n, checks, checks == 1 ? "" : "s", format_share(tolerance_used(*closest)), closest->group,
        entry_label(*closest), timing);
  } else {
    std::set<std::string> failed_groups;
    for (const CheckEntry* e : misses) failed_groups.insert(e->group);
    out << fmt::format("{} of {} check entries miss their tolerance, in {} of {} check{}. {}\n\n", misses.size(), n,
                       failed_groups.size(), checks, checks == 1 ? "" : "s", timing);
    for (size_t i = 0; i < misses.size() && i < kMissesShown; ++i) {
      const CheckEntry& e = *misses[i];
      const CheckSpec* spec = spec_of(run, e);
      const std::string unit = unit_of_column(e.column);
      out << fmt::format("- *{}*, {}: {} against {} ({}), error {} where {} is allowed: {} x the tolerance\n", e.group,
                         entry_label(e), format_quantity(e.computed, unit), format_quantity(e.reference, unit),
                         relation_symbol(e.relation), entry_error(e, spec), entry_tolerance(e, spec),
                         format_share(tolerance_used(e)));
    }
    if (misses.size() > kMissesShown)
      out << fmt::format("- and {} more misses (all in the checks below)\n", misses.size() - kMissesShown);
    out << '\n';
  }
}

void write_check_table(std::ostream& out, const RunRecord& run) {
  if (run.checks.empty() && run.check_specs.empty()) return;
  out << "## Checks\n\nAn entry passes when |computed - reference| <= abs_tol + rel_tol * |reference| (expect `=`), "
         "or, one-sided, when computed <= reference + tolerance (`<=`) or computed >= reference - tolerance (`>=`). "
         "*Used*: the share of its tolerance the check's worst entry uses (above 1: a miss). Full precision: "
         "`summary.json`.\n\n";
  out << "| check | expect | entries | pass | worst entry | computed | reference | error | tolerance | used | "
         "reference: file and source |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::string> groups;
  for (const CheckSpec& spec : run.check_specs) groups.push_back(spec.name);
  for (const CheckEntry& e : run.checks)
    if (std::find(groups.begin(), groups.end(), e.group) == groups.end()) groups.push_back(e.group);
  for (const std::string& group : groups) {
    const CheckEntry* worst = nullptr;
    int n = 0, failed = 0;
    for (const CheckEntry& e : run.checks) {
      if (e.group != group) continue;
      ++n;
      failed += e.pass ? 0 : 1;
      if (!worst || tolerance_used(e) > tolerance_used(*worst)) worst = &e;
    }
    const CheckSpec* spec = spec_of(run, group);
    std::string reference = "-", paired;
    if (spec) {
      reference = !spec->reference_case.empty() && spec->reference_result.empty()
                      ? fmt::format("`{}`, numbered by the modes of `{}`", spec->reference.filename().string(),
                                    spec->reference_case.filename().string())
                  : !spec->reference_case.empty()  ? fmt::format("result {} of `{}`", spec->reference_result,
                                                                 spec->reference_case.filename().string())
                  : spec->reference_result.empty() ? fmt::format("`{}`", spec->reference.filename().string())
                                                   : "result " + spec->reference_result;
      paired = pairing(*spec);
    }
    const std::string expect = spec ? relation_symbol(spec->relation) : worst ? relation_symbol(worst->relation) : "-";
    const std::string against =
        spec ? reference + paired + (spec->source.empty() ? std::string() : ": " + table_cell(spec->source)) : "-";
    if (!worst) {
      out << fmt::format("| {} | {} | 0 | - | - | - | - | - | - | - | {} |\n", table_cell(group), expect, against);
      continue;
    }
    const std::string unit = unit_of_column(worst->column);
    out << fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", table_cell(group), expect, n,
                       failed == 0 ? std::string("pass") : fmt::format("**FAIL** ({} of {})", failed, n),
                       table_cell(entry_label(*worst)), format_quantity(worst->computed, unit),
                       format_quantity(worst->reference, unit), entry_error(*worst, spec),
                       entry_tolerance(*worst, spec), share_cell(tolerance_used(*worst)), against);
  }
  out << fmt::format("\n<details><summary>Every entry ({})</summary>\n\n", run.checks.size());
  out << "| entry | computed | reference | abs error | rel error | tolerance | used | pass |\n"
         "|---|---|---|---|---|---|---|---|\n";
  for (const CheckEntry& e : run.checks) {
    const std::string unit = unit_of_column(e.column);
    out << fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} | {} |\n", table_cell(e.name), format_quantity(e.computed, unit),
        format_quantity(e.reference, unit), format_quantity(e.abs_error, unit),
        e.reference != 0.0 && std::isfinite(e.rel_error) ? unsigned_percent(e.rel_error) : std::string("-"),
        format_quantity(e.tolerance, unit), format_share(tolerance_used(e)), e.pass ? "pass" : "**FAIL**");
  }
  out << "\n</details>\n\n";
}

}  // namespace bb
