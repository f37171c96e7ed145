#include "report/writers.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/user_text.hpp"
#include "report/output_folder.hpp"

namespace bb {
namespace {

std::ofstream open_for_writing(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out.precision(17);
  return out;
}

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

// Every string of `j`, keys too, through printable(): summary.json shows user bytes as the
// terminal and report.md do (\xHH), and its writer cannot fail on them.
nlohmann::json printable_json(const nlohmann::json& j) {
  if (j.is_string()) return printable(j.get_ref<const std::string&>(), true);
  if (j.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const nlohmann::json& e : j) out.push_back(printable_json(e));
    return out;
  }
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [k, v] : j.items()) out[printable(k)] = printable_json(v);
    return out;
  }
  return j;
}

}  // namespace

std::string status_name(RunStatus status) {
  switch (status) {
    case RunStatus::pass:
      return "pass";
    case RunStatus::fail:
      return "fail";
    case RunStatus::no_checks:
      return "no_checks";
    case RunStatus::bad_input:
      return "bad_input";
    case RunStatus::solver_failed:
      return "solver_failed";
  }
  return "?";
}

int exit_code(RunStatus status) {
  switch (status) {
    case RunStatus::pass:
    case RunStatus::no_checks:
      return 0;
    case RunStatus::fail:
      return 1;
    case RunStatus::bad_input:
      return 2;
    case RunStatus::solver_failed:
      return 3;
  }
  return 3;
}

void write_table_csv(const ResultTable& table, const std::filesystem::path& file) {
  std::ofstream out = open_for_writing(file);
  std::vector<std::string> header = table.columns;
  for (const std::string& c : table.text_columns) header.push_back(csv_field(c));
  out << fmt::format("{}\n", fmt::join(header, ","));
  for (Eigen::Index r = 0; r < table.values.rows(); ++r) {
    out << std::lround(table.values(r, 0));
    for (Eigen::Index c = 1; c < table.values.cols(); ++c) out << fmt::format(",{:.12g}", table.values(r, c));
    for (const auto& column : table.text) out << ',' << csv_field(printable(column[static_cast<size_t>(r)], true));
    out << '\n';
  }
  if (!out) throw std::runtime_error("failed writing " + file.string());
}

void write_result_csv(const ResultTable& table, const std::filesystem::path& folder, RunRecord& run,
                      const std::string& file) {
  const std::string name = file.empty() ? table.name + ".csv" : file;
  // Table names made of user names (reduced models, cases) were checked by the case parser.
  if (name.find_first_of(std::string("/\\\0", 3)) != std::string::npos || name.starts_with("."))
    throw std::logic_error(fmt::format("result table '{}' cannot name a file", printable(table.name)));
  write_table_csv(table, folder / name);
  if (file.empty()) run.tables.push_back(name);
  for (Eigen::Index c = 1; c < table.values.cols(); ++c) {
    NonFiniteColumn n{name, table.columns[static_cast<size_t>(c)], table.columns.front(), {}};
    for (Eigen::Index r = 0; r < table.values.rows(); ++r)
      if (!std::isfinite(table.values(r, c))) n.keys.push_back(std::lround(table.values(r, 0)));
    if (!n.keys.empty()) run.non_finite.push_back(std::move(n));
  }
}

void write_summary_json(const RunRecord& run, const std::filesystem::path& file) {
  nlohmann::json j;
  j["case"] = run.case_name;
  j["case_file"] = run.case_file.string();
  j["status"] = status_name(run.status);
  j["wall_time_s"] = run.wall_seconds;
  j["fidelity"] = run.fidelity.empty() ? std::string("case settings") : run.fidelity;
  if (!run.message.empty()) j["message"] = run.message;
  if (!run.warnings.empty()) j["warnings"] = run.warnings;
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  j["checks"] = nlohmann::json::array();
  double worst = -std::numeric_limits<double>::infinity();
  for (const CheckEntry& c : run.checks) {
    const double used = tolerance_used(c);
    worst = std::max(worst, used);
    j["checks"].push_back({{"name", c.name},
                           {"group", c.group},
                           {"column", c.column},
                           {"key", c.key},
                           {"computed", number(c.computed)},
                           {"reference", number(c.reference)},
                           {"abs_error", number(c.abs_error)},
                           {"rel_error", number(c.rel_error)},
                           {"tolerance", c.tolerance},
                           {"relation", relation_symbol(c.relation)},
                           {"tolerance_used", number(used)},
                           {"pass", c.pass}});
  }
  // The largest share of its tolerance any entry uses (null: no checks, or a failed entry without
  // a finite error).
  j["worst_tolerance_used"] = run.checks.empty() ? nlohmann::json(nullptr) : number(worst);
  j["key_plots"] = nlohmann::json::array();
  for (const std::string& name : run.key_plots)
    for (const Plot& p : run.plots)
      if (p.name == name && !p.file.empty()) j["key_plots"].push_back(p.file);
  nlohmann::json facts = nlohmann::json::object();
  for (const auto& [k, v] : run.facts) facts[k] = v;
  j["facts"] = facts;
  j["tables"] = run.tables;
  j["non_finite"] = nlohmann::json::array();
  for (const NonFiniteColumn& n : run.non_finite)
    j["non_finite"].push_back({{"file", n.file}, {"column", n.column}, {"key_column", n.key_column}, {"keys", n.keys}});
  std::ofstream out = open_for_writing(file);
  // printable_json escapes every invalid byte; `replace` is the backstop that keeps dump() from throwing.
  out << printable_json(j).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  if (!out) throw std::runtime_error("failed writing " + file.string());
}

}  // namespace bb
