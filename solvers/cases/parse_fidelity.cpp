// [fidelity] -> FidelitySpec: the target, the compared table and the axes, checked against the case.
#include "cases/parse_fidelity.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

struct SettingInfo {
  FidelitySetting setting;
  const char* applies_to;  // for messages
  bool integer;
};

const std::map<std::string, SettingInfo>& settings() {
  static const std::map<std::string, SettingInfo> known = {
      {"analysis.harmonics", {FidelitySetting::harmonics, "an hbm analysis", true}},
      {"analysis.time_samples", {FidelitySetting::time_samples, "an hbm analysis", true}},
      {"analysis.model.modes", {FidelitySetting::reduced_modes, "an hbm analysis with a Craig-Bampton model", true}},
      {"analysis.steps_per_period", {FidelitySetting::steps_per_period, "a time analysis", true}},
      {"analysis.steady_tolerance", {FidelitySetting::steady_tolerance, "a time analysis", false}},
      {"mesh.refinement", {FidelitySetting::mesh_refinement, "a mapped_quad, hex_blocks or two_blade mesh", true}},
  };
  return known;
}

bool applies(FidelitySetting setting, const CaseSpec& spec) {
  const auto* hbm = std::get_if<HbmSpec>(&spec.analysis);
  const MeshSpec::Kind mesh = spec.model.mesh.kind;
  switch (setting) {
    case FidelitySetting::harmonics:
    case FidelitySetting::time_samples:
      return hbm != nullptr;
    case FidelitySetting::reduced_modes:
      return hbm && !hbm->model.matrices && hbm->model.file.empty();
    case FidelitySetting::steps_per_period:
    case FidelitySetting::steady_tolerance:
      return std::holds_alternative<TimeSpec>(spec.analysis);
    case FidelitySetting::mesh_refinement:
      return mesh == MeshSpec::Kind::mapped_quad || mesh == MeshSpec::Kind::hex_blocks ||
             mesh == MeshSpec::Kind::two_blade;
  }
  return false;
}

// Levels run from cheapest to finest: more of a count, a smaller tolerance.
void check_levels(TomlReader& r, const SettingInfo& info, const std::vector<double>& levels) {
  if (levels.size() < 2) r.fail("levels", "needs at least two levels, cheapest first");
  for (size_t i = 0; i < levels.size(); ++i) {
    const double v = levels[i];
    if (info.integer && (v < 1 || v != std::floor(v) || v > 1e6))
      r.fail("levels", fmt::format("entry {} ({}) must be a whole number in [1, 1e6]", i + 1, v));
    if (!(v > 0)) r.fail("levels", fmt::format("entry {} ({}) must be > 0", i + 1, v));
    if (i == 0) continue;
    const bool finer = info.setting == FidelitySetting::steady_tolerance ? v < levels[i - 1] : v > levels[i - 1];
    if (!finer)
      r.fail("levels", fmt::format("entry {} ({}) is not finer than the one before ({}): levels run cheapest first{}",
                                   i + 1, v, levels[i - 1],
                                   info.setting == FidelitySetting::steady_tolerance ? " (tolerances decreasing)"
                                                                                     : " (increasing)"));
  }
  if (info.setting == FidelitySetting::time_samples && levels.front() < 8)
    r.fail("levels", "AFT samples below 8 cannot resolve a stick-slip cycle");
  if (info.setting == FidelitySetting::harmonics && levels.back() > 50) r.fail("levels", "H must lie in [1, 50]");
}

}  // namespace

FidelitySpec parse_fidelity(TomlReader& top, const CaseSpec& spec) {
  TomlReader r(top.table("fidelity"), "fidelity", top.file());
  FidelitySpec f;
  f.at = r.location();
  f.target = r.positive("target");
  if (f.target >= 1) r.fail("target", "is a relative error: give a value below 1, e.g. 1e-3");
  f.result = r.name("result");
  f.columns = r.string_array("columns");
  if (f.columns.empty()) r.fail("columns", "name at least one column of the result table");
  for (size_t i = 0; i < f.columns.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (f.columns[i] == f.columns[j]) r.fail("columns", fmt::format("'{}' is named twice", f.columns[i]));
  f.key = r.optional_label("key").value_or("");
  f.note = r.optional_label("note", true).value_or("");
  if (!r.has("axes")) r.fail("axes", "name at least one axis, e.g. { setting = \"analysis.harmonics\", levels = [1, 3, 5] }");
  {
    const toml::array& axes = r.array("axes");
    if (axes.empty()) r.fail("axes", "name at least one axis");
    int index = 0;
    for (const toml::node& n : axes) {
      if (!n.is_table()) r.fail("axes", "write each axis as { setting = \"...\", levels = [...] }");
      TomlReader a(*n.as_table(), fmt::format("fidelity.axes[{}]", index++), r.file());
      FidelityAxisSpec axis;
      axis.at = a.location();
      axis.path = a.string("setting");
      const auto it = settings().find(axis.path);
      if (it == settings().end()) {
        std::string known;
        for (const auto& [name, info] : settings()) known += (known.empty() ? "" : ", ") + name;
        a.fail("setting", fmt::format("unknown setting '{}'; known: {}", axis.path, known));
      }
      axis.setting = it->second.setting;
      if (!applies(axis.setting, spec))
        a.fail("setting", fmt::format("'{}' needs {}", axis.path, it->second.applies_to));
      for (const FidelityAxisSpec& other : f.axes)
        if (other.setting == axis.setting) a.fail("setting", fmt::format("'{}' is already an axis", axis.path));
      axis.levels = a.number_array("levels");
      check_levels(a, it->second, axis.levels);
      a.finish();
      f.axes.push_back(std::move(axis));
    }
  }
  r.finish();
  // Every level must make a valid case: apply each once now, so a bad level fails at parse time.
  for (const FidelityAxisSpec& axis : f.axes)
    for (double level : axis.levels) {
      CaseSpec trial = spec;
      apply_fidelity_level(trial, axis, level);
      if (const auto* hbm = std::get_if<HbmSpec>(&trial.analysis);
          hbm && hbm->time_samples != 0 && hbm->time_samples < 2 * hbm->harmonics + 1)
        throw InputError(fmt::format("{}: fidelity: {} AFT samples cannot carry H = {} (need at least 2 H + 1)",
                                     axis.at.where(), hbm->time_samples, hbm->harmonics));
    }
  return f;
}

void apply_fidelity_level(CaseSpec& spec, const FidelityAxisSpec& axis, double level) {
  const int n = static_cast<int>(std::lround(level));
  switch (axis.setting) {
    case FidelitySetting::harmonics:
      std::get<HbmSpec>(spec.analysis).harmonics = n;
      return;
    case FidelitySetting::time_samples:
      std::get<HbmSpec>(spec.analysis).time_samples = n;
      return;
    case FidelitySetting::reduced_modes:
      std::get<HbmSpec>(spec.analysis).model.modes = n;
      return;
    case FidelitySetting::steps_per_period:
      std::get<TimeSpec>(spec.analysis).steps_per_period = n;
      return;
    case FidelitySetting::steady_tolerance:
      std::get<TimeSpec>(spec.analysis).steady_tolerance = level;
      return;
    case FidelitySetting::mesh_refinement: {
      MeshSpec& mesh = spec.model.mesh;
      if (mesh.kind == MeshSpec::Kind::mapped_quad) {
        mesh.mapped.nx *= n;
        mesh.mapped.ny *= n;
      } else if (mesh.kind == MeshSpec::Kind::hex_blocks) {
        for (HexBlockSpec& b : mesh.blocks) {
          b.nx *= n;
          b.ny *= n;
          b.nz *= n;
        }
      } else {
        mesh.two_blade.refinement *= n;
      }
      return;
    }
  }
}

}  // namespace bb
