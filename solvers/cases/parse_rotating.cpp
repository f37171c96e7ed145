#include "cases/parse_rotating.hpp"

#include <fmt/format.h>

#include <cmath>

namespace bb {
namespace {

double finite_positive(TomlReader& r, const std::string& key) {
  const double v = r.number(key);
  if (!(v > 0.0) || !std::isfinite(v)) r.fail(key, fmt::format("must be a positive finite number, found {}", v));
  return v;
}

// [x, y] or [x, y, z] (z = 0 when left out).
Eigen::Vector3d parse_vector(TomlReader& r, const std::string& key) {
  const std::vector<double> v = r.number_array(key);
  if (v.size() != 2 && v.size() != 3) r.fail(key, "expected [x, y] or [x, y, z]");
  Eigen::Vector3d out(v[0], v[1], v.size() == 3 ? v[2] : 0.0);
  if (!out.allFinite()) r.fail(key, "components must be finite");
  return out;
}

void parse_profile(TomlReader& r, RotatingSpec& s) {
  if (r.has("torque_n_m")) {
    s.profile = RotatingSpec::Profile::torque;
    s.torque = r.number("torque_n_m");
    s.initial_speed = r.number("initial_speed_rad_s");
    if (!std::isfinite(s.torque) || !std::isfinite(s.initial_speed))
      r.fail("torque_n_m", "torque and initial speed must be finite");
    s.rotor_inertia = finite_positive(r, "rotor_inertia");
    if (r.has("speed_rad_s") || r.has("spin_up_s"))
      r.fail("speed_rad_s", "a rotor driven by a torque has no prescribed speed");
    return;
  }
  s.speed = finite_positive(r, "speed_rad_s");
  if (r.has("spin_up_s")) {
    s.profile = RotatingSpec::Profile::spin_up;
    s.spin_up_time = finite_positive(r, "spin_up_s");
  }
  s.rotor_inertia = r.non_negative("rotor_inertia", 0.0);
}

void parse_axis(TomlReader& r, RotatingSpec& s) {
  const toml::table* t = r.optional_table("axis");
  if (!t) return;
  TomlReader a(*t, r.path() + ".axis", r.file());
  if (a.has("point")) s.axis_point = parse_vector(a, "point");
  if (a.has("direction")) {
    s.axis_direction = parse_vector(a, "direction");
    if (std::abs(s.axis_direction.norm() - 1.0) > 1e-9)
      a.fail("direction", fmt::format("must be a unit vector, |a| = {:.9g}", s.axis_direction.norm()));
  }
  a.finish();
}

void parse_campbell(TomlReader& r, RotatingSpec& s) {
  const toml::table* t = r.optional_table("campbell");
  if (!t) return;
  TomlReader c(*t, r.path() + ".campbell", r.file());
  if (c.has("speeds_rad_s")) {
    s.campbell_speeds = c.number_array("speeds_rad_s");
    for (double w : s.campbell_speeds)
      if (!(w >= 0.0) || !std::isfinite(w)) c.fail("speeds_rad_s", "speeds must be finite and >= 0");
    if (s.campbell_speeds.size() < 2 || !std::is_sorted(s.campbell_speeds.begin(), s.campbell_speeds.end()))
      c.fail("speeds_rad_s", "needs at least two speeds in ascending order");
  }
  if (const auto m = c.optional_integer("modes")) {
    if (*m < 1 || *m > 100) c.fail("modes", "must lie in [1, 100]");
    s.campbell_modes = static_cast<int>(*m);
  }
  if (c.has("engine_orders")) {
    s.engine_orders.clear();
    for (long eo : c.integer_array("engine_orders")) {
      if (eo < 1 || eo > 200) c.fail("engine_orders", "engine orders must lie in [1, 200]");
      s.engine_orders.push_back(static_cast<int>(eo));
    }
  }
  c.finish();
}

}  // namespace

RotatingSpec parse_rotating(TomlReader& r) {
  RotatingSpec s;
  s.at = r.location();
  parse_profile(r, s);
  parse_axis(r, s);
  if (r.has("gravity")) s.gravity = parse_vector(r, "gravity");
  s.end_time = finite_positive(r, "end_time_s");
  if (r.has("time_step_s")) {
    s.time_step = finite_positive(r, "time_step_s");
    if (s.time_step > s.end_time)
      r.fail("time_step_s", fmt::format("{} s exceeds end_time_s = {} s", s.time_step, s.end_time));
    if (s.end_time / s.time_step > kMaxRotatingSteps)
      r.fail("time_step_s", "more than 5e7 steps: choose a larger step");
  }
  if (r.has("rho_infinity")) {
    s.rho_infinity = r.number("rho_infinity");
    if (!(s.rho_infinity >= 0.0 && s.rho_infinity <= 1.0)) r.fail("rho_infinity", "must lie in [0, 1]");
  }
  s.stiffening = r.boolean("stiffening", s.stiffening);
  s.coriolis = r.boolean("coriolis", s.coriolis);
  s.compare_stiffening = r.boolean("compare_stiffening", s.compare_stiffening);
  s.modal_basis = r.choice("elastic_coordinates", {"modal", "nodal"}, "modal") == "modal";
  if (const auto m = r.optional_integer("basis_modes")) {
    if (*m < 1 || *m > 2000) r.fail("basis_modes", "must lie in [1, 2000]");
    s.basis_modes = static_cast<int>(*m);
  }
  if (r.has("histories")) s.histories = r.string_array("histories");
  if (r.has("history_interval_s")) s.history_interval = finite_positive(r, "history_interval_s");
  parse_campbell(r, s);
  if (s.modal_basis && s.campbell_modes >= s.basis_modes)
    r.fail("basis_modes", fmt::format("a modal basis of {} modes cannot converge {} rotating modes: raise basis_modes",
                                      s.basis_modes, s.campbell_modes));
  return s;
}

}  // namespace bb
