// [study] -> StudySpec: one accuracy-vs-cost study, checked against the analysis it studies.
#include "cases/parse_study.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "cases/parse_common.hpp"
#include "mesh/element_topology.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// A node set the model defines (checked here, so that an unknown one fails with or without --study).
std::string known_set(TomlReader& r, const std::string& key, const ModelSpec& model) {
  const std::string name = r.string(key);
  std::vector<std::string> names;
  for (const NodeSetSpec& s : model.sets) names.push_back(s.name);
  if (std::find(names.begin(), names.end(), name) == names.end())
    r.fail(key, fmt::format("no node set '{}' in [sets] (the sets are: {})", name,
                            names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "))));
  return name;
}

RefinementStudySpec parse_refinement_study(TomlReader r, const ModelSpec& model) {
  RefinementStudySpec s;
  s.at = r.location();
  r.choice("kind", {"refinement"});
  for (long level : r.integer_array("levels")) {
    if (level < 1) r.fail("levels", "refinement factors must be >= 1");
    // A repeated level solves the same mesh twice and fits a convergence order to no refinement.
    if (!s.levels.empty() && level <= s.levels.back())
      r.fail("levels", fmt::format("the levels must increase ({} follows {})", level, s.levels.back()));
    s.levels.push_back(static_cast<int>(level));
  }
  if (s.levels.size() < 3) r.fail("levels", "need at least 3 levels to estimate a convergence order");
  s.probe_set = known_set(r, "probe_set", model);
  s.probe_direction = parse_direction(r, "probe_direction", r.string("probe_direction"));
  if (r.has("load_split")) s.load_split = parse_split(r, "load_split");
  if (r.has("load_set")) s.load_set = known_set(r, "load_set", model);
  TomlReader ref(r.table("reference"), r.path() + ".reference", r.file());
  ref.choice("kind", {"timoshenko_cantilever"});
  s.beam_length = ref.positive("length");
  s.beam_height = ref.positive("height");
  s.beam_load = ref.number("load");
  s.shear_coefficient = ref.optional_number("shear_coefficient").value_or(s.shear_coefficient);
  if (!(s.shear_coefficient > 0)) ref.fail("shear_coefficient", "must be > 0");
  ref.finish();
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

HbmHarmonicsStudySpec parse_hbm_study(TomlReader r, const HbmSpec& hbm) {
  HbmHarmonicsStudySpec s;
  s.at = r.location();
  r.choice("kind", {"hbm_harmonics"});
  for (long h : r.integer_array("harmonics")) {
    if (h < 1 || h > 50) r.fail("harmonics", "each H must lie in [1, 50]");
    s.harmonics.push_back(static_cast<int>(h));
  }
  if (s.harmonics.size() < 2) r.fail("harmonics", "needs at least two values; the largest is the reference");
  s.force_levels = r.number_array("force_levels");
  for (double f : s.force_levels)
    if (std::find(hbm.force_levels.begin(), hbm.force_levels.end(), f) == hbm.force_levels.end())
      r.fail("force_levels", fmt::format("{} N is not one of the analysis's force_levels", f));
  if (s.force_levels.empty()) r.fail("force_levels", "needs at least one level");
  const long samples = r.optional_integer("time_samples").value_or(0);
  const int h_max = *std::max_element(s.harmonics.begin(), s.harmonics.end());
  if (samples != 0 && samples < 2 * h_max + 1)
    r.fail("time_samples", fmt::format("must be 0 or at least 2 H + 1 = {}", 2 * h_max + 1));
  s.time_samples = static_cast<int>(samples);
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

TimeStepStudySpec parse_time_study(TomlReader r) {
  TimeStepStudySpec s;
  s.at = r.location();
  r.choice("kind", {"time_steps"});
  for (long n : r.integer_array("steps_per_period")) {
    if (n < 8 || n > 100000) r.fail("steps_per_period", "each value must lie in [8, 100000]");
    s.steps_per_period.push_back(static_cast<int>(n));
  }
  s.steady_tolerances = r.number_array("steady_tolerances");
  for (double t : s.steady_tolerances)
    if (!(t > 0 && t < 0.1)) r.fail("steady_tolerances", "each value must lie in (0, 0.1)");
  if (s.steps_per_period.empty() || s.steady_tolerances.empty() ||
      s.steps_per_period.size() * s.steady_tolerances.size() < 2)
    r.fail("steps_per_period",
           "needs at least two variants; the finest (most steps, smallest tolerance) is the reference");
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

RomStudySpec parse_rom_study(TomlReader r) {
  RomStudySpec s;
  s.at = r.location();
  r.choice("kind", {"rom_modes"});
  for (long m : r.integer_array("modes")) {
    if (m < 0 || m > 1000) r.fail("modes", "mode counts must lie in 0..1000");
    s.modes.push_back(static_cast<int>(m));
  }
  if (s.modes.empty()) r.fail("modes", "needs at least one mode count");
  TomlReader sets(r.table("master_sets"), r.path() + ".master_sets", r.file());
  sets.labels_as_keys();
  for (const auto& [k, v] : r.table("master_sets")) {
    const std::string name(k.str());
    s.master_sets.emplace_back(name, sets.string_array(name));
    if (s.master_sets.back().second.empty()) sets.fail(name, "needs at least one master point");
  }
  sets.finish();
  if (s.master_sets.empty()) r.fail("master_sets", "needs at least one set, e.g. { thesis = [\"T1\", \"T2\"] }");
  if (const auto m = r.optional_integer("compare_modes")) {
    if (*m < 1) r.fail("compare_modes", "must be >= 1");
    s.compare_modes = static_cast<int>(*m);
  }
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

ModalRefinementStudySpec parse_modal_study(TomlReader r) {
  ModalRefinementStudySpec s;
  s.at = r.location();
  r.choice("kind", {"modal_refinement"});
  for (long level : r.integer_array("refinements")) {
    if (level < 1 || level > 16) r.fail("refinements", "levels must lie in 1..16");
    if (!s.refinements.empty() && level <= s.refinements.back())
      r.fail("refinements", fmt::format("the levels must increase ({} follows {})", level, s.refinements.back()));
    s.refinements.push_back(static_cast<int>(level));
  }
  if (s.refinements.size() < 2) r.fail("refinements", "need at least 2 levels");
  for (const std::string& e : r.string_array("elements")) {
    const std::optional<ElementType> t = element_type_named(e);
    if (!t || topology(*t).dimension != 3)
      r.fail("elements", fmt::format("unknown solid element '{}'; expected hex8, hex8i or hex20", e));
    s.elements.push_back(*t);
  }
  if (s.elements.empty()) r.fail("elements", "needs at least one element type");
  if (const auto m = r.optional_integer("modes")) {
    if (*m < 1) r.fail("modes", "must be >= 1");
    s.modes = static_cast<int>(*m);
  }
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

RotatingFidelityStudySpec parse_rotating_fidelity_study(TomlReader r) {
  RotatingFidelityStudySpec s;
  s.at = r.location();
  r.choice("kind", {"rotating_fidelity"});
  for (long m : r.integer_array("basis_modes")) {
    if (m < 1 || m > 500) r.fail("basis_modes", "each basis size must lie in [1, 500]");
    s.basis_modes.push_back(static_cast<int>(m));
  }
  if (s.basis_modes.empty()) r.fail("basis_modes", "needs at least one modal basis size");
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

}  // namespace

StudySpec parse_study(TomlReader& top, const ModelSpec& model, const AnalysisSpec& analysis) {
  const toml::table& study = top.table("study");
  const fs::path& file = top.file();
  const toml::node* kind = study.get("kind");
  const std::string k = kind ? kind->value<std::string>().value_or("") : "";
  if (k == "rom_modes") {
    RomStudySpec s = parse_rom_study(TomlReader(study, "study", file));
    const FrfSpec* frf = std::get_if<FrfSpec>(&analysis);
    if (!frf || !frf->full_model) top.fail("study", "a rom_modes study needs an frf analysis with the full model");
    if (s.compare_modes > frf->full_modes) top.fail("study", "compare_modes exceeds the analysis's full_modes");
    return s;
  }
  if (k == "time_steps") {
    if (!std::holds_alternative<TimeSpec>(analysis)) top.fail("study", "a time_steps study needs a time analysis");
    return parse_time_study(TomlReader(study, "study", file));
  }
  if (k == "hbm_harmonics") {
    const HbmSpec* hbm = std::get_if<HbmSpec>(&analysis);
    if (!hbm) top.fail("study", "an hbm_harmonics study needs an hbm analysis");
    return parse_hbm_study(TomlReader(study, "study", file), *hbm);
  }
  if (k == "rotating_fidelity") {
    if (!std::holds_alternative<RotatingSpec>(analysis))
      top.fail("study", "a rotating_fidelity study needs a rotating analysis");
    return parse_rotating_fidelity_study(TomlReader(study, "study", file));
  }
  if (k == "modal_refinement") {
    ModalRefinementStudySpec s = parse_modal_study(TomlReader(study, "study", file));
    const bool solid = model.mesh.kind == MeshSpec::Kind::two_blade || model.mesh.kind == MeshSpec::Kind::hex_blocks;
    if (!solid || !std::holds_alternative<ModalSpec>(analysis))
      top.fail("study", "a modal_refinement study needs a two_blade or hex_blocks mesh and a modal analysis");
    return s;
  }
  if (model.mesh.kind != MeshSpec::Kind::mapped_quad || !std::holds_alternative<StaticSpec>(analysis))
    top.fail("study", "a refinement study needs a mapped_quad mesh and a static analysis");
  return parse_refinement_study(TomlReader(study, "study", file), model);
}

}  // namespace bb
