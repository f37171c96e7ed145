#include "cases/parse_base_motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cases/base_motion_file.hpp"
#include "cases/parse_frf.hpp"
#include "cases/parse_hbm.hpp"

namespace bb {
namespace {

// Beyond it a harmonic balance of the base's distortion would not be run anyway (max_harmonics).
constexpr long kMaxBaseOrder = 64;

std::vector<BaseHarmonic> written_harmonics(TomlReader& b) {
  std::vector<BaseHarmonic> out;
  int i = 0;
  for (const toml::node& n : b.array("harmonics")) {
    if (!n.is_table()) b.fail("harmonics", "write each harmonic as { order = 3, ratio = 0.1, phase_deg = 30.0 }");
    TomlReader h(*n.as_table(), fmt::format("{}.harmonics[{}]", b.path(), i++), b.file());
    BaseHarmonic harmonic;
    harmonic.order = static_cast<int>(h.integer("order", 2, kMaxBaseOrder));
    harmonic.ratio = h.number("ratio");
    if (!(harmonic.ratio >= 0.0) || !std::isfinite(harmonic.ratio) || harmonic.ratio > 1e3)
      h.fail("ratio",
             fmt::format("the acceleration relative to harmonic 1's must lie in [0, 1e3], found {}", harmonic.ratio));
    harmonic.phase_deg = h.optional_number("phase_deg").value_or(0.0);
    if (!std::isfinite(harmonic.phase_deg) || std::abs(harmonic.phase_deg) > 1e4)
      h.fail("phase_deg", "must be a finite angle [deg] within +-1e4");
    h.finish();
    if (!out.empty() && harmonic.order <= out.back().order)
      h.fail("order", fmt::format("orders must increase strictly: {} follows {}", harmonic.order, out.back().order));
    out.push_back(harmonic);
  }
  return out;
}

}  // namespace

BaseMotionSpec parse_base_motion(TomlReader& analysis, const std::filesystem::path& folder,
                                 std::vector<double>& levels) {
  TomlReader b(analysis.table("base_motion"), analysis.path() + ".base_motion", analysis.file());
  BaseMotionSpec s;
  s.at = analysis.location("base_motion");
  s.influence = parse_combination(b, "influence");
  if (b.has("file") && b.has("harmonics"))
    b.fail("file", "give the base's harmonics in `harmonics` or read them from `file`, not both");
  double measured_level = 0.0;  // a measured period's own first harmonic: the default level
  if (b.has("file")) {
    if (b.has("phase_deg")) b.fail("phase_deg", "the measured period sets every phase: leave out phase_deg");
    const std::filesystem::path file = b.input_file("file", folder);
    const long periods = b.optional_integer("periods", 1, 100000).value_or(1);
    const long highest = b.optional_integer("highest_order", 1, kMaxBaseOrder).value_or(9);
    s.harmonics =
        base_harmonics_from_file(b, file, static_cast<int>(periods), static_cast<int>(highest), measured_level);
    s.file = file.string();
  } else {
    for (const char* key : {"periods", "highest_order"})
      if (b.has(key)) b.fail(key, "applies to a measured period (`file`)");
    BaseHarmonic first;
    first.phase_deg = b.optional_number("phase_deg").value_or(0.0);
    if (!std::isfinite(first.phase_deg) || std::abs(first.phase_deg) > 1e4)
      b.fail("phase_deg", "must be a finite angle [deg] within +-1e4");
    s.harmonics = {first};
    if (b.has("harmonics"))
      for (const BaseHarmonic& h : written_harmonics(b)) s.harmonics.push_back(h);
  }
  if (b.has("levels") || s.file.empty()) {
    levels = b.number_array("levels");
    if (levels.empty()) b.fail("levels", "needs at least one base acceleration [m/s^2]");
  } else {
    levels = {measured_level};
  }
  for (size_t i = 0; i < levels.size(); ++i)
    if (!(levels[i] > 0.0) || !std::isfinite(levels[i]) || levels[i] > 1e9)
      b.fail("levels", fmt::format("every level must be a base acceleration in (0, 1e9] m/s^2, entry {} is {}", i + 1,
                                   levels[i]));
  check_levels(b, "levels", levels, "base acceleration", "m/s^2");
  b.finish();
  return s;
}

void refuse_base_motion_misfits(TomlReader& analysis, const HbmSpec& spec, bool harmonic_balance) {
  const BaseMotionSpec& b = *spec.base_motion;
  if (spec.cyclic || spec.gap_damper)
    analysis.fail(spec.cyclic ? "cyclic" : "gap_damper",
                  "a cyclic sector is driven by an engine order's force pattern, not by a base motion");
  if (!spec.response_controls.empty() && b.harmonics.size() > 1)
    analysis.fail(
        "response_control",
        fmt::format("the held response's force scales harmonic 1 alone: a base motion with harmonic {} cannot "
                    "be controlled that way (drop the base's higher harmonics, or run a stepped sine)",
                    b.harmonics[1].order));
  const int reach = spec.harmonic_tolerance > 0.0 ? std::max(spec.harmonics, spec.max_harmonics) : spec.harmonics;
  if (harmonic_balance && b.highest_order() > reach)
    analysis.fail("base_motion",
                  fmt::format("the base moves at harmonic {} but the balance keeps H = {}: raise harmonics (or lower "
                              "the base's highest_order{})",
                              b.highest_order(), reach, b.file.empty() ? ", or drop that harmonic" : ""));
}

}  // namespace bb
