// TOML case file -> CaseSpec. The format is documented in cases/README.md.
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <string>
#include <vector>

#include "cases/case_spec.hpp"
#include "cases/parse_common.hpp"
#include "cases/parse_contact_loop.hpp"
#include "cases/parse_contact_modal.hpp"
#include "cases/parse_cyclic_modal.hpp"
#include "cases/parse_fidelity.hpp"
#include "cases/parse_frf.hpp"
#include "cases/parse_hbm.hpp"
#include "cases/parse_modal.hpp"
#include "cases/parse_model.hpp"
#include "cases/parse_nonlinear_modal.hpp"
#include "cases/parse_rotating.hpp"
#include "cases/parse_study.hpp"
#include "cases/parse_time.hpp"
#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// The parser of each analysis type, by its name in the case file; one per alternative of
// AnalysisSpec (checked below), so that a new type cannot be forgotten here.
struct AnalysisParser {
  std::string_view type;
  AnalysisSpec (*parse)(TomlReader& r, const fs::path& folder);
};
constexpr AnalysisParser kAnalysisParsers[] = {
    {"static",
     [](TomlReader& r, const fs::path&) -> AnalysisSpec {
       return StaticSpec{.integration_point_stresses = r.boolean("integration_point_stresses", false)};
     }},
    {"modal", [](TomlReader& r, const fs::path&) -> AnalysisSpec { return parse_modal(r); }},
    {"frf", [](TomlReader& r, const fs::path& folder) -> AnalysisSpec { return parse_frf(r, folder); }},
    {"hbm", [](TomlReader& r, const fs::path& folder) -> AnalysisSpec { return parse_hbm(r, folder); }},
    {"time", [](TomlReader& r, const fs::path& folder) -> AnalysisSpec { return parse_time(r, folder); }},
    {"contact_loop", [](TomlReader& r, const fs::path&) -> AnalysisSpec { return parse_contact_loop(r); }},
    {"rotating", [](TomlReader& r, const fs::path&) -> AnalysisSpec { return parse_rotating(r); }},
    {"contact_modal", [](TomlReader& r, const fs::path&) -> AnalysisSpec { return parse_contact_modal(r); }},
    {"cyclic_modal", [](TomlReader& r, const fs::path&) -> AnalysisSpec { return parse_cyclic_modal(r); }},
    {"nonlinear_modal",
     [](TomlReader& r, const fs::path& folder) -> AnalysisSpec { return parse_nonlinear_modal(r, folder); }},
};
static_assert(std::size(kAnalysisParsers) == std::variant_size_v<AnalysisSpec>, "one parser per analysis type");

AnalysisSpec parse_analysis(TomlReader r, const fs::path& folder) {
  std::vector<std::string> types;
  for (const AnalysisParser& p : kAnalysisParsers) types.emplace_back(p.type);
  const std::string type = r.choice("type", types);
  const auto parser = std::find_if(std::begin(kAnalysisParsers), std::end(kAnalysisParsers),
                                   [&](const AnalysisParser& p) { return p.type == type; });
  AnalysisSpec a = parser->parse(r, folder);
  const bool labels_modes = std::holds_alternative<ModalSpec>(a) || std::holds_alternative<FrfSpec>(a);
  if (!labels_modes && r.has("pairs"))
    r.fail("pairs", "[analysis.pairs] labels modes; it needs type = \"modal\" or \"frf\"");
  r.finish();
  return a;
}

// What an analysis needs of the case's model sections.
enum class ModelNeed {
  mesh,      // a mesh (and material) is required
  matrices,  // the analysis brings its matrices (reduced models, lumped matrices); a mesh is optional
  nothing,   // the analysis takes no model data at all
};
ModelNeed model_need(const StaticSpec&) { return ModelNeed::mesh; }
ModelNeed model_need(const ModalSpec&) { return ModelNeed::mesh; }
ModelNeed model_need(const FrfSpec& s) {
  const bool masters = std::any_of(s.roms.begin(), s.roms.end(), [](const RomSpec& r) { return !r.masters.empty(); });
  return s.full_model || masters ? ModelNeed::mesh : ModelNeed::matrices;
}
ModelNeed model_need(const HbmSpec& s) { return s.model.masters.empty() ? ModelNeed::matrices : ModelNeed::mesh; }
ModelNeed model_need(const TimeSpec& s) { return model_need(s.system); }
ModelNeed model_need(const ContactLoopSpec&) { return ModelNeed::nothing; }
ModelNeed model_need(const RotatingSpec&) { return ModelNeed::mesh; }
ModelNeed model_need(const ContactModalSpec&) { return ModelNeed::mesh; }
ModelNeed model_need(const CyclicModalSpec&) { return ModelNeed::mesh; }
ModelNeed model_need(const NonlinearModalSpec&) { return ModelNeed::nothing; }

// One of `kinds` by its case-file name (`name_of`), `fallback` when the key is absent.
template <class Kind, size_t N, class Name>
Kind named_kind(TomlReader& r, const std::string& key, const std::array<Kind, N>& kinds, Name name_of, Kind fallback) {
  std::vector<std::string> names;
  for (Kind k : kinds) names.emplace_back(name_of(k));
  const std::string chosen = r.choice(key, names, std::string(name_of(fallback)));
  for (Kind k : kinds)
    if (name_of(k) == chosen) return k;
  return fallback;
}

CheckSpec parse_check(TomlReader r, const fs::path& folder) {
  CheckSpec c;
  c.at = r.location();
  c.name = r.label("name");
  c.result = r.label("result");  // whether the analysis makes it is known only when it runs
  if (r.has("reference") == r.has("reference_result"))
    r.fail("reference", "give either 'reference' (a CSV file) or 'reference_result' (a result table of this run)");
  if (r.has("reference"))
    c.reference = r.input_file("reference", folder);
  else
    c.reference_result = r.label("reference_result");
  c.match = named_kind(r, "match", kMatches, match_name, CheckSpec::Match::key);
  if (r.has("reference_case")) {
    // With match = "mac" a reference file may be keyed by the other case's modes (e.g. published
    // values numbered as on the benchmark's own mesh): its run pairs them with this run's modes.
    if (c.reference_result.empty() && c.match != CheckSpec::Match::mac)
      r.fail("reference_case",
             "names the case whose result table 'reference_result' is compared with (or, with match = \"mac\", "
             "whose modes the keys of 'reference' number)");
    c.reference_case = r.input_file("reference_case", folder);
    if (const std::string why = file_problem(c.reference_case); !why.empty())
      r.fail("reference_case", fmt::format("no case file {} ({})", c.reference_case.string(), why));
  }
  c.relation = named_kind(r, "expect", kRelations, relation_name, CheckSpec::Relation::equal);
  if (c.match == CheckSpec::Match::mac && c.reference_case.empty())
    r.fail("match",
           "\"mac\" pairs this run's modes with the modes of another case's run by shape: give reference_case (and "
           "reference_result = \"frequencies\")");
  if (r.has("min_mac")) {
    if (c.match != CheckSpec::Match::mac) r.fail("min_mac", "applies to match = \"mac\" only");
    c.min_mac = r.number("min_mac");
    if (!(c.min_mac > 0 && c.min_mac <= 1)) r.fail("min_mac", fmt::format("must lie in (0, 1], found {}", c.min_mac));
  }
  if (r.has("labels")) {
    if (c.match != CheckSpec::Match::label) r.fail("labels", "applies to match = \"label\" only");
    c.labels = r.string_array("labels");
    for (const std::string& label : c.labels)
      if (const std::string problem = label_problem(label); !problem.empty()) r.fail("labels", problem);
  }
  if (c.match == CheckSpec::Match::label && c.labels.empty())
    r.fail("match", "\"label\" pairs rows by text columns: give labels = [\"type\", ...]");
  c.key = r.label("key");
  if (c.match == CheckSpec::Match::mac && c.key != "mode")
    r.fail("key", "match = \"mac\" pairs modes: the key is \"mode\"");
  TomlReader compare(r.table("compare"), r.path() + ".compare", r.file());
  compare.labels_as_keys();
  for (const auto& [k, v] : r.table("compare")) {
    const std::string result_column(k.str());
    c.compare.emplace_back(result_column, compare.label(result_column));
  }
  if (c.compare.empty()) r.fail("compare", "needs at least one 'result_column = \"reference_column\"' pair");
  if (r.has("keys")) {
    c.keys = r.integer_array("keys");
    if (c.keys.empty()) r.fail("keys", "empty list (leave 'keys' out to compare every reference row)");
    std::vector<long> sorted = c.keys;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) r.fail("keys", "a key is listed twice");
  }
  if (!r.has("abs_tol") && !r.has("rel_tol")) r.fail("", "a check needs abs_tol and/or rel_tol");
  c.abs_tol = r.non_negative("abs_tol", 0.0);
  c.rel_tol = r.non_negative("rel_tol", 0.0);
  c.source = r.optional_label("source").value_or("");
  r.finish();
  return c;
}

toml::table read_case_table(const fs::path& file, int depth) {
  if (const std::string why = file_problem(file); !why.empty())
    throw InputError(fmt::format("{}: case file not found ({})", file.string(), why));
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(
        fmt::format("{}:{}: TOML syntax error: {}", file.string(), e.source().begin.line, e.description()));
  }
  // [case] model_from: material, mesh, sets, constraints and section of another case, so that
  // several analyses of one article share a single description of it.
  const toml::node* from = root.at_path("case.model_from").node();
  if (!from) return root;
  const SourceLocation at{file, static_cast<int>(from->source().begin.line)};
  if (!from->is_string()) throw InputError(fmt::format("{}: 'case.model_from': expected a case file name", at.where()));
  if (depth > 8) throw InputError(fmt::format("{}: 'case.model_from': more than 8 levels (a cycle?)", at.where()));
  const fs::path base_file = file.parent_path() / from->value<std::string>().value();
  if (const std::string why = file_problem(base_file); why == "it is a directory")
    throw InputError(printable(
        fmt::format("{}: 'case.model_from': {} is a folder; name a case file", at.where(), base_file.string())));
  else if (!why.empty())
    throw InputError(printable(
        fmt::format("{}: 'case.model_from': case file {} not found ({})", at.where(), base_file.string(), why)));
  const toml::table base = read_case_table(base_file, depth + 1);
  parse_case_table(base, base_file);  // errors in the base name the base file and its lines
  for (const char* key : {"material", "mesh", "sets", "bc", "section"}) {
    if (root.contains(key))
      throw InputError(fmt::format("{}: '{}' is given here and by model_from = \"{}\"; keep one", at.where(), key,
                                   base_file.filename().string()));
    if (const toml::node* n = base.get(key)) root.insert(key, *n);
  }
  return root;
}

}  // namespace

toml::table read_case_table(const fs::path& file) { return read_case_table(file, 0); }

CaseSpec parse_case_file(const fs::path& file) { return parse_case_table(read_case_table(file), file); }

CaseSpec parse_case_table(const toml::table& root, const fs::path& file) {
  const fs::path folder = file.parent_path();
  TomlReader top(root, "", file);
  CaseSpec spec;
  spec.file = file;
  {
    TomlReader c(top.table("case"), "case", file);
    // The name is the report folder's name (bladebench run without --out): no path may hide in it.
    if (c.has("name")) {
      spec.name = c.string("name");
      if (const std::string problem = dotted_name_problem(spec.name); !problem.empty())
        c.fail("name", problem + "; a case name is the name of its report folder");
    } else {
      spec.name = file.stem().string();
      if (const std::string problem = dotted_name_problem(spec.name); !problem.empty())
        throw InputError(printable(fmt::format(
            "{}: the file name cannot be the case name (the name of its report folder): {}; give [case] name",
            file.string(), problem)));
    }
    spec.title = c.optional_label("title").value_or(spec.name);
    spec.description = c.optional_label("description", true).value_or("");
    if (c.has("key_plots")) {
      spec.key_plots_at = c.location("key_plots");
      for (const std::string& plot : c.string_array("key_plots")) {
        if (const std::string problem = dotted_name_problem(plot); !problem.empty())
          c.fail("key_plots",
                 fmt::format("'{}': {}; a key plot is named by its file's stem", printable(plot), problem));
        // Each copy would be drawn (and inlined) again: 5 000 made a 1 GB report.html.
        if (std::find(spec.key_plots.begin(), spec.key_plots.end(), plot) != spec.key_plots.end())
          c.fail("key_plots", fmt::format("'{}' is named twice", printable(plot)));
        spec.key_plots.push_back(plot);
      }
    }
    if (const auto from = c.optional_string("model_from")) spec.model_from = folder / *from;
    spec.vtk = c.boolean("vtk", false);
    c.finish();
  }
  spec.analysis = parse_analysis(TomlReader(top.table("analysis"), "analysis", file), folder);
  const ModelNeed need = std::visit([](const auto& a) { return model_need(a); }, spec.analysis);
  if (need == ModelNeed::nothing) {
    for (const char* key : {"material", "mesh", "section", "sets", "bc", "load"})
      if (top.has(key))
        top.fail(key, std::holds_alternative<ContactLoopSpec>(spec.analysis)
                          ? "a contact_loop analysis drives one contact by an imposed motion: it takes no model data"
                          : "a nonlinear_modal analysis is its own model (backbone, mass): it takes no model data");
    spec.model.mesh.kind = MeshSpec::Kind::none;
  } else if (need == ModelNeed::matrices && !top.has("mesh")) {
    for (const char* key : {"material", "section", "sets", "bc", "load"})
      if (top.has(key))
        top.fail(key,
                 "the model is given by matrices only (a reduced model from a file or written in the case): it takes "
                 "no mesh data");
    spec.model.mesh.kind = MeshSpec::Kind::none;
  } else {
    spec.model = parse_model(top, folder, !std::holds_alternative<StaticSpec>(spec.analysis));
    if (!spec.model.contact_pairs.empty() && !std::holds_alternative<ContactModalSpec>(spec.analysis))
      throw InputError(
          fmt::format("{}: [[contact]] pairs are solved by type = \"contact_modal\" only; this "
                      "analysis would ignore them",
                      spec.model.contact_pairs.front().at.where()));
  }
  for_each_table_in_array(top, "check",
                          [&](TomlReader r) { spec.checks.push_back(parse_check(std::move(r), folder)); });
  if (top.has("study")) spec.study = parse_study(top, spec.model, spec.analysis);
  if (top.has("fidelity")) spec.fidelity = parse_fidelity(top, spec);
  top.has("calibration");  // read by parse_calibration (cases/parse_calibration.hpp)
  top.finish();
  return spec;
}

}  // namespace bb
