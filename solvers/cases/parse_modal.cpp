#include "cases/parse_modal.hpp"

#include <algorithm>

#include "cases/parse_common.hpp"

namespace bb {

ModalSpec parse_modal(TomlReader& r) {
  ModalSpec a;
  if (r.has("band_hz")) {
    const auto band = r.number_array("band_hz");
    if (band.size() != 2 || band[0] < 0 || band[0] >= band[1])
      r.fail("band_hz", "expected [f_min, f_max] with 0 <= f_min < f_max");
    a.modes.band_min_hz = band[0];
    a.modes.band_max_hz = band[1];
  }
  const auto modes = r.optional_integer("modes");
  if (!modes && !a.modes.band_max_hz) r.fail("modes", "missing required key (or give band_hz)");
  if (modes && *modes < 1) r.fail("modes", "must be >= 1");
  // With a band, `modes` is the first guess of how many modes lie below its top.
  a.modes.lowest = static_cast<int>(modes.value_or(20));
  a.options.shift_frequency_hz = r.optional_number("shift_hz").value_or(a.options.shift_frequency_hz);
  a.options.tolerance = r.optional_number("tolerance").value_or(a.options.tolerance);
  a.options.eigensolver = parse_eigensolver(r);
  a.options.out_of_core = parse_out_of_core(r, a.options.eigensolver);
  if (!(a.options.tolerance > 0.0 && a.options.tolerance < 1.0))
    r.fail("tolerance", fmt::format("must lie in (0, 1) (a relative eigen-residual), found {}", a.options.tolerance));
  a.pairs = parse_mode_pairs(r);
  if (r.has("stress_modes")) {
    for (long k : r.integer_array("stress_modes")) {
      if (k < 1 || k > a.modes.lowest)
        r.fail("stress_modes", fmt::format("mode {} is not among the {} modes asked for", k, a.modes.lowest));
      if (std::find(a.stress_modes.begin(), a.stress_modes.end(), static_cast<int>(k)) != a.stress_modes.end())
        r.fail("stress_modes", fmt::format("mode {} is listed twice", k));
      a.stress_modes.push_back(static_cast<int>(k));
    }
  }
  return a;
}

std::optional<ModePairSpec> parse_mode_pairs(TomlReader& r) {
  const toml::table* pairs = r.optional_table("pairs");
  if (!pairs) return std::nullopt;
  TomlReader p(*pairs, r.path() + ".pairs", r.file());
  ModePairSpec spec;
  spec.at = p.location();
  spec.left = p.string("left");
  spec.right = p.string("right");
  spec.direction = parse_direction(p, "direction", p.string("direction"));
  spec.left_tip = p.string("left_tip");
  spec.right_tip = p.string("right_tip");
  p.finish();
  return spec;
}

}  // namespace bb
