#include "cases/parse_cyclic_modal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cases/parse_common.hpp"

namespace bb {

CyclicModalSpec parse_cyclic_modal(TomlReader& r) {
  CyclicModalSpec s;
  s.at = r.location();
  s.sectors = static_cast<int>(r.integer("sectors", 2, 10000));
  s.left = r.optional_label("left").value_or(s.left);
  s.right = r.optional_label("right").value_or(s.right);
  if (s.left == s.right) r.fail("right", fmt::format("the two cyclic faces are one set, '{}'", s.left));
  if (auto t = r.optional_number("face_tolerance")) {
    if (!(*t > 0)) r.fail("face_tolerance", fmt::format("must be > 0 [m], found {}", *t));
    s.face_tolerance = *t;
  }
  s.families = static_cast<int>(r.optional_integer("families", 1, 1000).value_or(s.families));
  if (r.has("nodal_diameters")) {
    for (long k : r.integer_array("nodal_diameters", 0, s.sectors / 2)) {
      if (std::find(s.nodal_diameters.begin(), s.nodal_diameters.end(), k) != s.nodal_diameters.end())
        r.fail("nodal_diameters", fmt::format("nodal diameter {} is listed twice", k));
      s.nodal_diameters.push_back(static_cast<int>(k));
    }
    if (s.nodal_diameters.empty()) r.fail("nodal_diameters", "is empty (omit it for every nodal diameter)");
    std::sort(s.nodal_diameters.begin(), s.nodal_diameters.end());
  }
  s.options.shift_frequency_hz = r.optional_number("shift_hz").value_or(s.options.shift_frequency_hz);
  s.options.tolerance = r.optional_number("tolerance").value_or(s.options.tolerance);
  if (!(s.options.tolerance > 0.0 && s.options.tolerance < 1.0))
    r.fail("tolerance", fmt::format("must lie in (0, 1) (a relative eigen-residual), found {}", s.options.tolerance));
  s.options.eigensolver = parse_eigensolver(r);
  s.options.out_of_core = parse_out_of_core(r, s.options.eigensolver);
  s.whole = r.boolean("whole", false);
  if (const auto n = r.optional_integer("threads")) {
    if (*n < 1 || *n > 256)
      r.fail("threads", fmt::format("must lie in [1, 256] (nodal diameters solved at once), found {}", *n));
    s.threads = static_cast<int>(*n);
  }
  if (r.has("engine_orders")) {
    for (long eo : r.integer_array("engine_orders", 1, 100000)) s.engine_orders.push_back(static_cast<int>(eo));
    const auto rpm = r.optional_number("max_speed_rpm");
    if (!rpm || !(*rpm > 0)) r.fail("max_speed_rpm", "engine_orders need the top of the speed range, > 0 [rpm]");
    s.max_speed_rpm = *rpm;
  } else if (r.has("max_speed_rpm")) {
    r.fail("max_speed_rpm", "is read with engine_orders only");
  }
  if (r.has("speeds_rpm")) {
    s.speeds_rpm = r.number_array("speeds_rpm");
    if (s.speeds_rpm.size() < 2) r.fail("speeds_rpm", "needs at least two speeds (a Campbell diagram's axis)");
    for (size_t i = 0; i < s.speeds_rpm.size(); ++i)
      if (!(s.speeds_rpm[i] >= 0) || !std::isfinite(s.speeds_rpm[i]) || (i && !(s.speeds_rpm[i] > s.speeds_rpm[i - 1])))
        r.fail("speeds_rpm", "speeds must be finite, >= 0 and ascending [rpm]");
  }
  return s;
}

}  // namespace bb
